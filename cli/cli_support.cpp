#include "cli/cli_support.h"

#include <filesystem>
#include <iostream>

#include "io/input_error.h"
#include "voronoi/engine.h"

namespace covmap::cli {

int guarded(const std::function<int()>& body) {
  try {
    return body();
  } catch (const io::InputError& e) {
    std::cerr << "covmap: " << e.what() << "\n";
    return kBadInput;
  } catch (const voronoi::InvalidSites& e) {
    std::cerr << "covmap: " << e.what() << "\n";
    return kBadInput;
  } catch (const std::filesystem::filesystem_error& e) {
    std::cerr << "covmap: " << e.what() << "\n";
    return kBadInput;
  } catch (const std::invalid_argument& e) {
    std::cerr << "covmap: " << e.what() << "\n";
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << "covmap: internal error: " << e.what() << "\n";
    return kInternal;
  }
}

}  // namespace covmap::cli
