#include "io/json_fields.h"

#include <cmath>
#include <limits>

#include "core/round_trip_numbers.h"
#include "io/input_error.h"
#include "io/input_limits.h"
#include "io/text_util.h"

namespace covmap::io::detail {

FieldError::FieldError(std::string path_, std::string message_)
    : std::runtime_error(path_ + ": " + message_), path(std::move(path_)), message(std::move(message_)) {}

namespace {

// Refuses nesting deeper than kMaxJsonDepth before the JSON library sees the text (one linear
// pass; brackets inside strings do not count).
void check_nesting(std::string_view text, const std::string& file) {
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth)
        throw InputError(file, line_of_offset(text, i), "",
                         "JSON nested more than " + std::to_string(kMaxJsonDepth) + " levels deep at byte " +
                             std::to_string(i + 1) + "; covmap's formats nest at most 6 levels");
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

}  // namespace

Json parse_json(std::string_view text, const std::string& file) {
  // nlohmann's messages start with "[json.exception.parse_error.101] "; the tag helps nobody.
  const auto plain = [](const std::string& what) {
    const auto close = what.find("] ");
    return what.rfind("[json.exception", 0) == 0 && close != std::string::npos ? what.substr(close + 2) : what;
  };
  check_nesting(text, file);
  try {
    return Json::parse(text.begin(), text.end());
  } catch (const Json::parse_error& e) {
    // e.byte is 1-based and points just past the offending character.
    const std::size_t offset = e.byte > 0 ? e.byte - 1 : 0;
    throw InputError(file, line_of_offset(text, offset), "",
                     "invalid JSON at byte " + std::to_string(e.byte) + ": " + plain(e.what()));
  } catch (const Json::out_of_range& e) {
    // A number literal too large for a double ("number overflow parsing '1e999'"). nlohmann gives
    // no position, so find the quoted literal in the text for a line number.
    const std::string message = plain(e.what());
    int line = 0;
    if (const auto open = message.find('\''), close = message.rfind('\''); open != std::string::npos && close > open) {
      if (const auto at = text.find(message.substr(open + 1, close - open - 1)); at != std::string_view::npos) {
        line = line_of_offset(text, at);
      }
    }
    throw InputError(file, line, "", "invalid JSON: " + message);
  }
}

void check_format_tag(const Json& root, std::string_view expected, const std::string& file) {
  std::string want(1, '"');  // appended, not "\"" + ...: GCC 12 false -Wrestrict (PR 105651)
  want += expected;
  want += '"';
  if (!root.is_object()) {
    throw InputError(file, 0, "", "top level must be a JSON object with \"format\": " + want + " (got " + describe(root) + ")");
  }
  const auto it = root.find("format");
  if (it == root.end()) throw InputError(file, 0, "format", "missing; expected " + want);
  if (!it->is_string() || it->get_ref<const std::string&>() != expected) {
    throw InputError(file, 0, "format", "expected " + want + " (got " + describe(*it) + ")");
  }
}

std::string describe(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return value.get<bool>() ? "true" : "false";
    case Json::value_t::string: {
      std::string text = value.dump();
      if (text.size() > 40) text = text.substr(0, 37) + "...";
      return "string " + text;
    }
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float: return "number " + value.dump();
    case Json::value_t::object: return "an object";
    case Json::value_t::array: return "an array";
    default: return "an unsupported value";
  }
}

std::string member_path(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

std::string element_path(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

void expect_object(const Json& value, const std::string& path) {
  if (!value.is_object()) throw FieldError(path, "must be an object (got " + describe(value) + ")");
}

void expect_array(const Json& value, const std::string& path) {
  if (!value.is_array()) throw FieldError(path, "must be an array (got " + describe(value) + ")");
}

const Json& member(const Json& object, std::string_view key, const std::string& path) {
  expect_object(object, path);
  const auto it = object.find(key);
  if (it == object.end()) throw FieldError(member_path(path, key), "missing");
  return *it;
}

const Json* optional_member(const Json& object, std::string_view key) {
  if (!object.is_object()) return nullptr;
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

double number(const Json& value, const std::string& path) {
  if (!value.is_number()) throw FieldError(path, "must be a number (got " + describe(value) + ")");
  return value.get<double>();
}

double finite_number(const Json& value, const std::string& path) {
  const double x = number(value, path);
  // JSON has no NaN or infinity, but a literal like 1e999 overflows to infinity when parsed.
  if (!std::isfinite(x)) throw FieldError(path, "must be finite (got " + round_trip_number(x) + ")");
  return x;
}

bool boolean(const Json& value, const std::string& path) {
  if (!value.is_boolean()) throw FieldError(path, "must be true or false (got " + describe(value) + ")");
  return value.get<bool>();
}

int index(const Json& value, const std::string& path, std::size_t count, std::string_view what, bool allow_null) {
  if (value.is_null()) {
    if (allow_null) return -1;
    throw FieldError(path, "must be a " + std::string(what) + " index (got null)");
  }
  if (!value.is_number_integer()) {
    throw FieldError(path, "must be a " + std::string(what) + " index (got " + describe(value) + ")");
  }
  // is_number_integer() covers both signed and unsigned storage; compare without overflow.
  const bool negative = value.is_number_unsigned() ? false : value.get<std::int64_t>() < 0;
  if (negative || value.get<std::uint64_t>() >= count) {
    throw FieldError(path, std::string(what) + " index " + value.dump() + " out of range (" + std::to_string(count) + " " +
                               std::string(what) + (count == 1 ? "" : "s") + ")");
  }
  return static_cast<int>(value.get<std::uint64_t>());
}

std::string site_id(const Json& value, const std::string& path) {
  if (value.is_string()) {
    const auto& text = value.get_ref<const std::string&>();
    if (text.empty()) throw FieldError(path, "must not be empty");
    return text;
  }
  if (value.is_number_integer()) return value.dump();
  throw FieldError(path, "must be a string or an integer (got " + describe(value) + ")");
}

}  // namespace covmap::io::detail
