// What this runin is: the project version and the git description of the tree it was built from.
#pragma once

namespace runin::cli {

const char *runin_version();       // PROJECT_VERSION, e.g. "0.1.0"
const char *runin_git_describe();  // `git describe --always --dirty --tags` at build time, or "unknown"

}  // namespace runin::cli
