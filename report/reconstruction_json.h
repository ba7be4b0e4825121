// covmap.reconstruction/1: the answer of `covmap recognize` (docs/FORMATS.md).
#pragma once

#include <iosfwd>

#include "recognition/recognize.h"

namespace covmap::report {

void write_reconstruction_json(const recognition::Reconstruction& r, std::ostream& out);

}  // namespace covmap::report
