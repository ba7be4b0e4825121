#include "io/json_scan.h"

#include <charconv>
#include <cmath>

#include "io/input_limits.h"
#include "io/text_util.h"

namespace covmap::io::detail {

void JsonScan::skip_space() {
  while (at_ < text_.size()) {
    const char c = text_[at_];
    if (c != ' ' && c != '\n' && c != '\r' && c != '\t') return;
    ++at_;
  }
}

char JsonScan::peek() {
  skip_space();
  return at_ < text_.size() ? text_[at_] : '\0';
}

void JsonScan::expect(char c) {
  if (peek() != c) throw FastPathMiss{};
  ++at_;
}

void JsonScan::expect_end() {
  if (peek() != '\0' || at_ != text_.size()) throw FastPathMiss{};  // '\0' inside the text is not JSON
}

void JsonScan::open(char bracket) {
  expect(bracket);
  if (++depth_ > kMaxJsonDepth) throw FastPathMiss{};
}

bool JsonScan::next(char close, bool& first) {
  if (peek() == close) {  // in "[1,]" the "]" is read as the value after the comma, and misses
    ++at_;
    --depth_;
    return false;
  }
  if (!first) expect(',');
  first = false;
  return true;
}

std::string_view JsonScan::key() {
  expect('"');
  const std::size_t begin = at_;
  bool ascii = true;
  while (at_ < text_.size() && text_[at_] != '"') {
    const auto c = static_cast<unsigned char>(text_[at_]);
    if (c == '\\' || c < 0x20) throw FastPathMiss{};  // escapes would need decoding to compare
    if (c >= 0x80) ascii = false;
    ++at_;
  }
  if (at_ == text_.size()) throw FastPathMiss{};
  const std::string_view name = text_.substr(begin, at_ - begin);
  // Raw UTF-8 names occur in exported maps' properties ("Höhe"); the reference refuses invalid UTF-8.
  if (!ascii && !valid_utf8(std::string(name))) throw FastPathMiss{};
  ++at_;
  expect(':');
  return name;
}

void JsonScan::literal(std::string_view word) {
  if (text_.substr(at_, word.size()) != word) throw FastPathMiss{};
  at_ += word.size();
}

bool JsonScan::null() {
  if (peek() != 'n') return false;
  literal("null");
  return true;
}

bool JsonScan::boolean() {
  const char c = peek();
  if (c == 't') {
    literal("true");
    return true;
  }
  if (c != 'f') throw FastPathMiss{};
  literal("false");
  return false;
}

std::size_t JsonScan::digits() {
  const std::size_t begin = at_;
  while (at_ < text_.size() && text_[at_] >= '0' && text_[at_] <= '9') ++at_;
  return at_ - begin;
}

std::string_view JsonScan::number_token() {
  skip_space();
  const std::size_t begin = at_;
  if (at_ < text_.size() && text_[at_] == '-') ++at_;
  const std::size_t int_begin = at_;
  const std::size_t int_digits = digits();
  if (int_digits == 0 || (int_digits > 1 && text_[int_begin] == '0')) throw FastPathMiss{};
  if (at_ < text_.size() && text_[at_] == '.') {
    ++at_;
    if (digits() == 0) throw FastPathMiss{};
  }
  if (at_ < text_.size() && (text_[at_] == 'e' || text_[at_] == 'E')) {
    ++at_;
    if (at_ < text_.size() && (text_[at_] == '+' || text_[at_] == '-')) ++at_;
    if (digits() == 0) throw FastPathMiss{};
  }
  return text_.substr(begin, at_ - begin);
}

double JsonScan::number() {
  const std::string_view token = number_token();
  double value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  // Out of range (1e999, 1e-400): the reference reader's treatment decides.
  if (error != std::errc() || end != token.data() + token.size() || !std::isfinite(value)) throw FastPathMiss{};
  // The reference reads a token without fraction or exponent as an integer first, so "-0" is +0.
  if (value == 0 && token.find_first_of(".eE") == std::string_view::npos) return 0.0;
  return value;
}

int JsonScan::index(std::size_t count) {
  const std::string_view token = number_token();
  if (token.front() == '-' || token.find_first_of(".eE") != std::string_view::npos) throw FastPathMiss{};
  std::size_t value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || value >= count) throw FastPathMiss{};
  return static_cast<int>(value);
}

std::string_view JsonScan::integer_text() {
  const std::string_view token = number_token();
  const std::size_t sign = token.front() == '-' ? 1 : 0;
  if (token.find_first_of(".eE") != std::string_view::npos || token.size() - sign > kMaxIdDigits || token == "-0")
    throw FastPathMiss{};
  return token;
}

std::string JsonScan::string() {
  expect('"');
  std::string out;
  bool ascii = true;
  std::size_t plain = at_;  // start of the run copied as is
  for (; at_ < text_.size(); ++at_) {
    const auto c = static_cast<unsigned char>(text_[at_]);
    if (c == '"') break;
    if (c < 0x20) throw FastPathMiss{};
    if (c >= 0x80) ascii = false;
    if (c != '\\') continue;
    out.append(text_.substr(plain, at_ - plain));
    if (++at_ == text_.size()) throw FastPathMiss{};
    switch (text_[at_]) {
      case '"': out += '"'; break;
      case '\\': out += '\\'; break;
      case '/': out += '/'; break;
      case 'b': out += '\b'; break;
      case 'f': out += '\f'; break;
      case 'n': out += '\n'; break;
      case 'r': out += '\r'; break;
      case 't': out += '\t'; break;
      default: throw FastPathMiss{};  // \u and invalid escapes
    }
    plain = at_ + 1;
  }
  if (at_ == text_.size()) throw FastPathMiss{};
  out.append(text_.substr(plain, at_ - plain));
  ++at_;
  if (!ascii && !valid_utf8(out)) throw FastPathMiss{};
  return out;
}

std::string_view JsonScan::raw_value() {
  skip_space();
  const std::size_t begin = at_;
  skip_value();
  return text_.substr(begin, at_ - begin);
}

void JsonScan::skip_value() {
  switch (peek()) {
    case '{':
      open('{');
      for (bool first = true; next('}', first);) {
        key();
        skip_value();
      }
      return;
    case '[':
      open('[');
      for (bool first = true; next(']', first);) skip_value();
      return;
    case '"': (void)string(); return;
    case 't':
    case 'f': (void)boolean(); return;
    case 'n': (void)null(); return;
    default: (void)number(); return;
  }
}

}  // namespace covmap::io::detail
