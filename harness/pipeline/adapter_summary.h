// An adapter read back as people read it (`raygate adapter check`): what raygate will build and
// run, placeholders and all, how runs are timed (runner/timing/) and how images are judged, so a
// user can check an adapter before a CI job trips over it.
#pragma once

#include <string>

#include "adapter/adapter.h"

namespace raygate {

// "FILE: ok" and one indented line per field, each ending in a newline.
std::string adapter_summary(const Adapter& adapter);

}  // namespace raygate
