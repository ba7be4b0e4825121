#include "gis/gdal_support.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <mutex>

namespace covmap::gis::detail {

void init_gdal() {
  static std::once_flag once;
  std::call_once(once, [] {
    GDALAllRegister();
    CPLSetErrorHandler(CPLQuietErrorHandler);
  });
}

Dataset open_dataset(const std::string& path, unsigned kinds) {
  init_gdal();
  CPLErrorReset();
  return Dataset(GDALOpenEx(path.c_str(), kinds | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
}

std::string last_gdal_error(const std::string& fallback) {
  const char* message = CPLGetLastErrorMsg();
  return message && *message ? std::string(message) : fallback;
}

std::string memory_file_name(const std::string& suffix) {
  static std::atomic<unsigned long> counter{0};
  return "/vsimem/covmap_" + std::to_string(counter++) + suffix;
}

std::string take_memory_file(const std::string& name) {
  vsi_l_offset length = 0;
  GByte* data = VSIGetMemFileBuffer(name.c_str(), &length, FALSE);
  std::string bytes = data ? std::string(reinterpret_cast<const char*>(data), static_cast<std::size_t>(length)) : "";
  VSIUnlink(name.c_str());
  return bytes;
}

std::string ascii_lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::string driver_name(GDALDatasetH ds) {
  GDALDriverH driver = GDALGetDatasetDriver(ds);
  return driver ? GDALGetDriverShortName(driver) : "unknown";
}

}  // namespace covmap::gis::detail
