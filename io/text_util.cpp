#include "io/text_util.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "core/large_buffer.h"
#include "io/input_error.h"
#include "io/input_limits.h"
#include <nlohmann/json.hpp>

namespace covmap::io::detail {

std::string quote_id(std::string_view id) {
  std::string out = "'";
  for (const char c : id) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f) {
      static constexpr char kHex[] = "0123456789abcdef";
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 0xf];
    } else {
      out += c;
    }
  }
  return out + "'";
}

std::string read_text_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError(path.string(), 0, "", "cannot read file: it is a directory");
  }
  if (const auto size = std::filesystem::file_size(path, ec); !ec && size > kMaxInputFileBytes) {
    throw InputError(path.string(), 0, "",
                     "the file holds " + std::to_string(size >> 20) + " MiB; covmap reads at most " +
                         std::to_string(kMaxInputFileBytes >> 20) + " MiB per input (docs/RELIABILITY.md)");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw InputError(path.string(), 0, "", std::string("cannot open file: ") + std::strerror(errno));
  }
  // A regular file is read in one go into a string of its size: streaming it through an
  // ostringstream is slow on large files and holds up to twice the file in memory while it grows.
  // Anything else (a pipe, a file that changes size) goes through the stream.
  if (const auto size = std::filesystem::file_size(path, ec); !ec && std::filesystem::is_regular_file(path, ec)) {
    // In huge pages where the system has them: page by page, the first touch of a fresh 4 KiB page
    // cost more than parsing it (core/large_buffer.h).
    std::string content;
    content.reserve(size);
    advise_huge_pages(content.data(), content.capacity());
    content.resize(size);
    in.read(content.data(), static_cast<std::streamsize>(size));
    if (!in.bad() && static_cast<std::uintmax_t>(in.gcount()) == size && in.peek() == std::char_traits<char>::eof())
      return content;
    in.clear();
    in.seekg(0);
  }
  std::ostringstream content;
  content << in.rdbuf();
  if (in.bad()) throw InputError(path.string(), 0, "", "error while reading file");
  return std::move(content).str();
}

int line_of_offset(std::string_view text, std::size_t offset) {
  if (offset > text.size()) offset = text.size();
  int line = 1;
  for (std::size_t i = 0; i < offset; ++i) line += text[i] == '\n' ? 1 : 0;
  return line;
}

std::string_view trim(std::string_view text) {
  constexpr std::string_view kSpace = " \t\r\n\v\f";
  const auto first = text.find_first_not_of(kSpace);
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(kSpace);
  return text.substr(first, last - first + 1);
}

bool valid_utf8(const std::string& text) {
  try {
    (void)nlohmann::json(text).dump();
    return true;
  } catch (const nlohmann::json::type_error&) {
    return false;
  }
}

}  // namespace covmap::io::detail
