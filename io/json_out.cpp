#include "io/json_out.h"

#include <charconv>
#include <cstring>

#include "core/round_trip_numbers.h"
#include "io/text_util.h"

namespace covmap::io::detail {

bool valid_json_text(std::string_view text) {
  for (const char c : text) {
    if (static_cast<unsigned char>(c) >= 0x80) return valid_utf8(std::string(text));
  }
  return true;
}

char* JsonOut::room(std::size_t bytes) {
  if (used_ + bytes > kBufferBytes) flush();
  return buffer_.get() + used_;
}

void JsonOut::flush() {
  if (stream_) stream_->write(buffer_.get(), static_cast<std::streamsize>(used_));
  else text_->append(buffer_.get(), used_);
  used_ = 0;
}

void JsonOut::raw(std::string_view text) {
  if (text.size() > kBufferBytes) {
    flush();
    if (stream_) stream_->write(text.data(), static_cast<std::streamsize>(text.size()));
    else text_->append(text);
    return;
  }
  std::memcpy(room(text.size()), text.data(), text.size());
  used_ += text.size();
}

void JsonOut::number(double value) {
  char* at = room(kMaxJsonNumberChars);
  used_ += static_cast<std::size_t>(write_json_number(value, at) - at);
}

void JsonOut::integer(long long value) {
  char* at = room(kTokenBytes);
  used_ += static_cast<std::size_t>(std::to_chars(at, at + kTokenBytes, value).ptr - at);
}

void JsonOut::index_or_null(int index) {
  if (index < 0) raw("null");
  else integer(index);
}

void JsonOut::boolean(bool value) { raw(value ? "true" : "false"); }

void JsonOut::string(std::string_view text) {
  static constexpr char kHex[] = "0123456789abcdef";
  raw("\"");
  std::size_t plain = 0;  // start of the run of characters that need no escape
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c != '"' && c != '\\') continue;
    raw(text.substr(plain, i - plain));
    plain = i + 1;
    switch (c) {
      case '"': raw("\\\""); break;
      case '\\': raw("\\\\"); break;
      case '\b': raw("\\b"); break;
      case '\f': raw("\\f"); break;
      case '\n': raw("\\n"); break;
      case '\r': raw("\\r"); break;
      case '\t': raw("\\t"); break;
      default: {
        const char escape[] = {'\\', 'u', '0', '0', kHex[c >> 4], kHex[c & 0xf]};
        raw(std::string_view(escape, sizeof escape));
      }
    }
  }
  raw(text.substr(plain));
  raw("\"");
}

}  // namespace covmap::io::detail
