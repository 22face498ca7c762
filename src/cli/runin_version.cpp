#include "cli/runin_version.h"

#include "runin_git_describe.h"  // generated at build time (git_version.cmake)

namespace runin::cli {

const char *runin_version() { return RUNIN_VERSION; }
const char *runin_git_describe() { return RUNIN_GIT_DESCRIBE; }

}  // namespace runin::cli
