// Typed access to nlohmann::json values with errors that name the JSON path (internal to io/).
//
// The readers address every value by its path ("arcs[12].to") because JSON files written by
// programs are often one long line, where a line number says little. Helpers throw FieldError;
// each reader turns it into an InputError carrying its file name.
#pragma once

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <string_view>

namespace covmap::io::detail {

using Json = nlohmann::json;

struct FieldError : std::runtime_error {
  FieldError(std::string path_, std::string message_);
  std::string path;
  std::string message;
};

// Parses text as JSON. Syntax errors become InputError(file, line, "", "invalid JSON at byte N: ...").
Json parse_json(std::string_view text, const std::string& file);

// Throws InputError unless root is an object whose "format" is exactly `expected`.
void check_format_tag(const Json& root, std::string_view expected, const std::string& file);

// "string \"abc\"", "number 3", "null", "array", ... — what was found instead of what was wanted.
std::string describe(const Json& value);

std::string member_path(const std::string& path, std::string_view key);  // "a" + "b" -> "a.b"
std::string element_path(const std::string& path, std::size_t index);    // "a", 3 -> "a[3]"

void expect_object(const Json& value, const std::string& path);
void expect_array(const Json& value, const std::string& path);

// object[key]; throws FieldError "missing" if absent. path is the object's path.
const Json& member(const Json& object, std::string_view key, const std::string& path);
// object[key] or nullptr if absent.
const Json* optional_member(const Json& object, std::string_view key);

// Any number (integers are accepted as doubles); may be infinite after an overflowing literal.
double number(const Json& value, const std::string& path);
// A finite number.
double finite_number(const Json& value, const std::string& path);
bool boolean(const Json& value, const std::string& path);
// An index into a vector of `count` things called `what` ("node"); null gives -1 when allowed.
int index(const Json& value, const std::string& path, std::size_t count, std::string_view what, bool allow_null);
// A site id: a non-empty string, or an integer (written back as its decimal text).
std::string site_id(const Json& value, const std::string& path);

}  // namespace covmap::io::detail
