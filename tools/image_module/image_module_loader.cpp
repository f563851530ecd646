#include <dlfcn.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "image_module/image_module.hpp"

namespace edgewise::tools {
namespace {

// The module's file name, beside the tools (EDGEWISE_IMAGE_MODULE_NAME), and where the build
// put it (EDGEWISE_IMAGE_MODULE_PATH), for the programs elsewhere in the build tree (the tests).
std::vector<std::string> candidate_paths() {
  std::vector<std::string> paths;
  std::error_code error;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) paths.push_back((program.parent_path() / EDGEWISE_IMAGE_MODULE_NAME).string());
  paths.emplace_back(EDGEWISE_IMAGE_MODULE_PATH);
  return paths;
}

const ImageModule* load() {
  std::string reasons;
  for (const std::string& path : candidate_paths()) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) continue;
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      reasons += std::string(reasons.empty() ? "" : "; ") + ::dlerror();
      continue;
    }
    const auto entry = reinterpret_cast<ImageModuleEntry>(::dlsym(handle, "edgewise_image_module"));
    const ImageModule* module = entry != nullptr ? entry(kImageModuleVersion) : nullptr;
    if (module != nullptr) return module;  // loaded for the rest of the run
    reasons += std::string(reasons.empty() ? "" : "; ") + path +
               ": built from another version of the tools";
    ::dlclose(handle);
  }
  if (reasons.empty()) reasons = std::string("not found at ") + EDGEWISE_IMAGE_MODULE_PATH;
  throw std::runtime_error("cannot load the image module (OpenImageIO): " + reasons);
}

}  // namespace

const ImageModule& image_module() {
  // Initialized once, on first use; a failed load throws and is tried again at the next call.
  static const ImageModule* const module = load();
  return *module;
}

}  // namespace edgewise::tools
