// A strict, allocation-light scanner for the fast paths of the JSON readers (internal to io/).
//
// The fast readers (io/fast_readers.h) pull the fixed layouts of covmap.sites/1 and
// covmap.arcgraph/1 straight out of the text, with no JSON document in between. They handle a
// subset of valid JSON, and only well-formed files: whenever the text leaves that subset, or any
// check fails, they throw FastPathMiss and the caller reruns the reference (nlohmann DOM) reader,
// which is the single source of every error message. So the scanner never has to explain anything;
// it only has to be right about what it accepts:
//   - only RFC 8259 JSON: whitespace is space, tab, CR, LF; number tokens follow the grammar
//     exactly (no leading zeros, '+', '.5', '1.', hex, NaN); strings hold no raw control characters
//     and are valid UTF-8; literals are true/false/null;
//   - nesting at most kMaxJsonDepth (the reference reader refuses deeper text);
//   - misses, rather than handles: \u escapes in strings, escapes of any kind in member names (raw
//     UTF-8 names are taken), a byte order mark, and numbers that overflow or underflow
//     (std::from_chars reports them out of range);
//   - reads a number token without fraction or exponent as the reference does (through an integer,
//     so "-0" is +0.0).
// Numbers are converted by std::from_chars, correctly rounded like the reference's strtod.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace covmap::io::detail {

// "This text is not for the fast path": not an error, the reference reader decides.
struct FastPathMiss {};

class JsonScan {
 public:
  explicit JsonScan(std::string_view text) : text_(text) {}

  // Containers. Use as:  scan.open('{'); for (bool first = true; scan.next('}', first);) {...}
  // next() consumes the separating comma or the closing bracket (then returns false).
  void open(char bracket);
  bool next(char close, bool& first);
  // The next member name and its ':' (names with escapes miss; they would need decoding).
  std::string_view key();

  // Values.
  bool null();  // consumes `null` if it is next
  bool boolean();
  double number();
  // A non-negative integer token (no sign, fraction or exponent) below `count`; misses otherwise.
  int index(std::size_t count);
  // An integer token of at most kMaxIdDigits digits, returned as its text ("-12"); misses on "-0".
  std::string_view integer_text();
  std::string string();
  void skip_value();  // any valid JSON value
  // Skips any valid JSON value and returns its text, for a reader that hands a rare member to the
  // reference JSON library (a GeoJSON "crs").
  std::string_view raw_value();
  char peek();        // the next non-space character, '\0' at the end

  void expect_end();  // only whitespace may follow
  std::size_t remaining() const { return text_.size() - at_; }  // bytes not read yet

  // Integer ids longer than this may not fit in 64 bits, where the reference reader changes type.
  static constexpr std::size_t kMaxIdDigits = 18;

 private:
  void skip_space();
  void expect(char c);
  void literal(std::string_view word);
  std::string_view number_token();  // the exact token text, checked against the JSON grammar
  std::size_t digits();             // consumes [0-9]*, returns how many

  std::string_view text_;
  std::size_t at_ = 0;
  int depth_ = 0;
};

}  // namespace covmap::io::detail
