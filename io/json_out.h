// A buffered writer of JSON tokens onto an std::ostream or the end of a std::string (internal to
// io/): the arc graph and sites writers emit their fixed layouts through it, without building a
// JSON document, whose memory and time would dwarf the writing.
//
// Contract: tokens are appended to a fixed buffer that goes to the target in large writes; nothing
// is validated beyond what each method says (the caller writes the punctuation with raw() and is
// responsible for the structure). flush() must be called at the end; the destructor does not flush,
// so an exception thrown mid-way leaves at most the bytes of earlier full buffers in the stream.
#pragma once

#include <cstddef>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>

namespace covmap::io::detail {

// Whether `text` may go into JsonOut::string: valid UTF-8 (plain ASCII is recognized without the
// full check).
bool valid_json_text(std::string_view text);

class JsonOut {
 public:
  explicit JsonOut(std::ostream& out) : stream_(&out) {}
  explicit JsonOut(std::string& out) : text_(&out) {}
  JsonOut(const JsonOut&) = delete;
  JsonOut& operator=(const JsonOut&) = delete;

  void raw(std::string_view text);
  // A string literal: its length is known without strlen (the writers' punctuation and names).
  template <std::size_t N>
  void raw(const char (&literal)[N]) {
    raw(std::string_view(literal, N - 1));
  }
  void number(double value);     // finite (see core/round_trip_numbers.h); always a float token
  void integer(long long value);
  void index_or_null(int index);  // null for a negative index (kNone)
  void boolean(bool value);
  // A quoted string. Escapes '"', '\\' and control characters as nlohmann does; bytes >= 0x80 pass
  // through, so the text must be valid UTF-8 (the caller checks; see text_util.h valid_utf8).
  void string(std::string_view text);
  void flush();

 private:
  // Large enough that stream calls cost nothing next to formatting; small enough to stay in cache.
  static constexpr std::size_t kBufferBytes = std::size_t{1} << 16;
  // Room a single token may need before the buffer is flushed (a number, an integer, a literal).
  static constexpr std::size_t kTokenBytes = 64;

  char* room(std::size_t bytes);

  std::ostream* stream_ = nullptr;  // exactly one of the two targets
  std::string* text_ = nullptr;
  // 64 KiB: not on the stack; not zeroed either (every byte is written before it is read, and the
  // arc graph's writer makes one JsonOut per piece).
  std::unique_ptr<char[]> buffer_ = std::make_unique_for_overwrite<char[]>(kBufferBytes);
  std::size_t used_ = 0;
};

}  // namespace covmap::io::detail
