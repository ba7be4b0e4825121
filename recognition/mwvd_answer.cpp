#include "recognition/recognize.h"

namespace covmap::recognition {

std::string_view to_string(MwvdAnswer answer) {
  switch (answer) {
    case MwvdAnswer::kUnknown: return "unknown";
    case MwvdAnswer::kYes: return "yes";
    case MwvdAnswer::kNo: return "no";
  }
  return "unknown";  // unreachable: every enumerator is handled above
}

std::optional<MwvdAnswer> mwvd_answer_from_string(std::string_view name) {
  for (MwvdAnswer a : {MwvdAnswer::kUnknown, MwvdAnswer::kYes, MwvdAnswer::kNo})
    if (to_string(a) == name) return a;
  return std::nullopt;
}

}  // namespace covmap::recognition
