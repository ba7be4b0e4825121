// Small text helpers shared by the covmap::io readers and writers (internal to io/).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace covmap::io::detail {

// A site id for messages: 'b'. Control characters are shown as \xNN so a message stays one line.
std::string quote_id(std::string_view id);

// The whole file as bytes. Throws InputError naming the file if it cannot be opened or read.
std::string read_text_file(const std::filesystem::path& path);

// 1-based line number of a byte offset in text (offsets past the end count as the last line).
int line_of_offset(std::string_view text, std::size_t offset);

// text without surrounding spaces, tabs and carriage returns.
std::string_view trim(std::string_view text);

// Whether text is valid UTF-8. Ids end up in JSON, SVG and HTML, which need it; readers check at
// the line that holds the id, so the message can name it.
bool valid_utf8(const std::string& text);

}  // namespace covmap::io::detail
