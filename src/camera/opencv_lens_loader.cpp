// Opens libk40t_opencv_lens.so (camera/opencv_lens.h) on first use.
#include <dlfcn.h>
#include <unistd.h>

#include <climits>
#include <mutex>
#include <string>
#include <vector>

#include "k40t_driver/camera/opencv_lens.h"

namespace k40t::camera {

namespace {

std::string directory_of(const std::string& path) {
  const size_t slash = path.rfind('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

// Where to look, in order: beside the file that holds this code (the driver's library in lib/, or
// a program in the build's bin/), beside the running program, then the bare name (the library
// path: LD_LIBRARY_PATH, which catkin's setup files set, and the programs' run paths).
std::vector<std::string> candidates() {
  std::vector<std::string> out;
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&opencv_lens), &info) && info.dli_fname &&
      info.dli_fname[0] == '/')
    out.push_back(directory_of(info.dli_fname) + kOpenCvLensLibrary);
  char exe[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n > 0)
    out.push_back(directory_of(std::string(exe, static_cast<size_t>(n))) + kOpenCvLensLibrary);
  out.push_back(kOpenCvLensLibrary);
  return out;
}

Result<const OpenCvLens*> load() {
  std::string errors;
  for (const std::string& path : candidates()) {
    if (path.find('/') != std::string::npos && access(path.c_str(), F_OK) != 0) continue;
    void* library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);  // never closed
    if (!library) {
      errors += std::string("; ") + dlerror();
      continue;
    }
    using Entry = const OpenCvLens* (*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(library, kOpenCvLensSymbol));
    if (!entry) return Result<const OpenCvLens*>::fail(path + " has no " + kOpenCvLensSymbol);
    return entry();
  }
  return Result<const OpenCvLens*>::fail(
      std::string("lens distortion needs ") + kOpenCvLensLibrary +
      " (built with the driver), found neither beside the program nor on the library path" +
      errors);
}

}  // namespace

Result<const OpenCvLens*> opencv_lens() {
  static std::once_flag once;
  static Result<const OpenCvLens*> lens = Result<const OpenCvLens*>::fail("not loaded");
  std::call_once(once, [] { lens = load(); });
  return lens;
}

}  // namespace k40t::camera
