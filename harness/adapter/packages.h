// Which of an adapter's "requires" Debian packages are missing on this machine, so `adapter
// check` (and a failed build) can print the apt-get line instead of a compiler's complaint.
#pragma once

#include <string>
#include <vector>

#include "adapter/adapter.h"

namespace raygate {

// The packages of adapter.packages that dpkg does not report as installed, in adapter order.
// Asks `dpkg-query -W -f=${Status} PKG` per package (no shell). Throws InfraError when
// dpkg-query cannot be run at all (not a Debian system): then nothing can be said either way.
std::vector<std::string> missing_packages(const Adapter& adapter);

// "apt-get install -y a b" for a list of package names ("" if there are none).
std::string apt_get_line(const std::vector<std::string>& packages);

}  // namespace raygate
