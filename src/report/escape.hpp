#pragma once
/// The report stage's two escapers of case text: one for HTML and SVG (XML), one for Markdown.
/// Both show control characters and the invisible Unicode characters that reorder text
/// (core/printable.hpp) instead of passing them to a viewer.
#include <string>

namespace freestand::report {

/// HTML and XML text and attribute escape (& < > " '); control characters but line feed,
/// carriage return and tab show as \xNN, the reordering Unicode characters as \uXXXX.
std::string html_escape(const std::string& text);

/// Escapes text for a Markdown document: '<' and '&' as entities (no raw HTML can start),
/// Markdown punctuation backslash-escaped, line breaks folded to spaces; control characters
/// show as \xNN, the reordering Unicode characters as \uXXXX.
std::string markdown_escape(const std::string& text);

}  // namespace freestand::report
