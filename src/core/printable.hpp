#pragma once
/// Control characters from input text (ESC, BEL, NUL...) must not reach a terminal or a viewer
/// raw (issue 16 defect 10): they are shown as \xNN.
#include <string>
#include <string_view>

namespace freestand::core {

/// True for the ASCII control characters U+0000-U+001F and U+007F.
bool is_control(char c);

/// c as "\xNN" (two upper-case hex digits).
std::string visible_control(char c);

/// text with every control character but line feed and tab shown as \xNN: what an error
/// message quoting a file's bytes may print to a terminal.
std::string printable(std::string_view text);

}  // namespace freestand::core
