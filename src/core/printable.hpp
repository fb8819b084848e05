#pragma once
/// Control characters from input text (ESC, BEL, NUL...) must not reach a terminal or a viewer
/// raw: they are shown as \xNN. Nor must the invisible Unicode characters that reorder or break
/// the text around them (C1 controls, bidirectional formatting characters: a U+202E in a name
/// shows the verdict after it backwards): they are shown as \uXXXX.
#include <string>
#include <string_view>

namespace freestand::core {

/// True for the ASCII control characters U+0000-U+001F and U+007F.
bool is_control(char c);

/// c as "\xNN" (two upper-case hex digits).
std::string visible_control(char c);

/// text with the C1 controls (U+0080-U+009F), the bidirectional formatting characters
/// (U+061C, U+200E, U+200F, U+202A-U+202E, U+2066-U+2069) and the line and paragraph
/// separators (U+2028, U+2029) of its UTF-8 shown as "\uXXXX" (upper-case hex); every other
/// byte unchanged. What any text from an input may show in a report.
std::string visible_unicode_controls(std::string_view text);

/// text with every control character but line feed and tab shown as \xNN, and the characters
/// of visible_unicode_controls as \uXXXX: what an error message quoting a file's bytes may
/// print to a terminal.
std::string printable(std::string_view text);

/// A name (a component's, a case's, a file's) as one line of text: printable, with line feed,
/// carriage return and tab also shown, as \n, \r and \t. What a headline, a report's title or
/// a table cell may show of a name.
std::string printable_name(std::string_view name);

}  // namespace freestand::core
