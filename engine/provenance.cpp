#include "engine/provenance.h"

#include <unistd.h>

#include "shockmap_version.h"

namespace shockmap {

Provenance CurrentProvenance(int jobs) {
  Provenance p;
  p.code_version = SHOCKMAP_GIT_VERSION;  // git describe at build time
  p.build_type = SHOCKMAP_BUILD_TYPE;
#if defined(__clang__)
  p.compiler = "clang " __clang_version__;
#elif defined(__GNUC__)
  p.compiler = "gcc " __VERSION__;
#else
  p.compiler = "unknown";
#endif
  char host[256] = {};
  gethostname(host, sizeof host - 1);
  p.host = host;
  p.pid = getpid();
  p.jobs = jobs;
  return p;
}

}  // namespace shockmap
