#include "engine/provenance.h"

#include <unistd.h>

#include "shockmap_version.h"

namespace shockmap {

namespace {

constexpr const char* kCompiler =
#if defined(__clang__)
    "clang " __clang_version__;
#elif defined(__GNUC__)
    "gcc " __VERSION__;
#else
    "unknown";
#endif

}  // namespace

Provenance CurrentProvenance(int jobs) {
  Provenance p;
  p.code_version = SHOCKMAP_GIT_VERSION;  // git describe at build time
  p.build_type = SHOCKMAP_BUILD_TYPE;
  p.compiler = kCompiler;
  char host[256] = {};
  gethostname(host, sizeof host - 1);
  p.host = host;
  p.pid = getpid();
  p.jobs = jobs;
  return p;
}

std::string VersionLine() {
  return std::string("shockmap ") + SHOCKMAP_VERSION + " (git " + SHOCKMAP_GIT_VERSION + ", " +
         kCompiler + ", " + SHOCKMAP_BUILD_TYPE + ")";
}

}  // namespace shockmap
