// SPDX-License-Identifier: GPL-3.0-or-later
#include "image_files/image_files.h"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace bs::image_files {
namespace {

// The two functions' types as OpenCV declares them: the static_asserts below fail to compile if an OpenCV release
// changes either signature, before the mangled names (which encode these types) could go stale.
using ImreadFn = cv::Mat (*)(const cv::String&, int);
using ImwriteFn = bool (*)(const cv::String&, cv::InputArray, const std::vector<int>&);
static_assert(std::is_same_v<decltype(&cv::imread), ImreadFn>);
static_assert(std::is_same_v<decltype(&cv::imwrite), ImwriteFn>);

// Itanium C++ ABI names (GCC and clang on Linux, libstdc++'s std::string) of the two functions above.
constexpr const char* kImread = "_ZN2cv6imreadERKNSt7__cxx1112basic_stringIcSt11char_traitsIcESaIcEEEi";
constexpr const char* kImwrite =
    "_ZN2cv7imwriteERKNSt7__cxx1112basic_stringIcSt11char_traitsIcESaIcEEERKNS_11_InputArrayERKSt6vectorIiSaIiEE";

struct Codecs {
  ImreadFn imread = nullptr;
  ImwriteFn imwrite = nullptr;
};

// Loaded once, by the soname the build linked against (BENCHSCOPE_IMGCODECS_SONAME), so the library found is the
// one the package depends on. A failure is remembered and reported again on every call.
const Codecs& codecs() {
  static std::once_flag once;
  static Codecs loaded;
  static std::string error;
  std::call_once(once, [] {
    void* lib = ::dlopen(BENCHSCOPE_IMGCODECS_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
      const char* why = ::dlerror();
      error = std::string("cannot load OpenCV's image codecs (" BENCHSCOPE_IMGCODECS_SONAME "): ") +
              (why ? why : "unknown reason") + "; install the package that holds it";
      return;
    }
    loaded.imread = reinterpret_cast<ImreadFn>(::dlsym(lib, kImread));
    loaded.imwrite = reinterpret_cast<ImwriteFn>(::dlsym(lib, kImwrite));
    if (!loaded.imread || !loaded.imwrite)
      error = "OpenCV's image codecs (" BENCHSCOPE_IMGCODECS_SONAME ") lack cv::imread or cv::imwrite";
  });
  if (!error.empty()) throw std::runtime_error(error);
  return loaded;
}

}  // namespace

cv::Mat read(const std::string& path, int flags) { return codecs().imread(path, flags); }

bool write(const std::string& path, const cv::Mat& image) { return codecs().imwrite(path, image, {}); }

}  // namespace bs::image_files
