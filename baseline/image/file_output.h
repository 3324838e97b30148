// The baseline's output files (the image of -o, the --stats JSON) replaced whole or not at all:
// the bytes go to a temporary file in the same folder, renamed over the old file only once they
// are all written. A full disk used to leave a truncated or empty image under the old name.
#pragma once

#include <string>
#include <string_view>

namespace raygate {

// Writes `bytes` to `path` through a temporary beside it; on failure returns false, leaves any
// old file as it was, removes the temporary, and puts the reason (naming `path`) in `error`.
// A `path` that exists and is not a regular file (/dev/null, a FIFO) is written straight
// through instead: renaming over it would replace the node. No fsync: the baseline is timed by
// its process, and a sync would add the disk's latency to every measured run, which the tracer
// under test does not pay; this guards against a failed write, not against a power cut.
bool write_file_replacing(const std::string& path, std::string_view bytes, std::string& error);

}  // namespace raygate
