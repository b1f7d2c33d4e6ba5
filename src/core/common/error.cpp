#include "flexmbd/common/error.hpp"

#include <cstdio>
#include <cstdlib>

namespace flexmbd {
namespace internal {

void AbortOnFailedDemand(const char* condition, const char* file, int line) {
  std::fprintf(stderr, "flexmbd internal error: %s failed at %s:%d\n", condition, file, line);
  std::abort();
}

}  // namespace internal
}  // namespace flexmbd
