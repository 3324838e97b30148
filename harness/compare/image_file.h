// An image file read as it is now. OpenImageIO's shared ImageCache keeps what it learned of a
// file by name; a file rewritten in place within one process (another size) was read with the
// spec it had before, past the end of the new buffer (a crash found blessing a run's images
// after their first bless). Every image raygate decodes is opened through here.
#pragma once

#include <OpenImageIO/imagebuf.h>

#include <filesystem>
#include <string>

namespace raygate {

OIIO_NAMESPACE::ImageBuf current_image(const std::filesystem::path& path);

// Why `buf` (opened by current_image, not yet read) is not decoded: its header declares more
// pixels than any render raygate compares (134 million; a 1 MB PNG of 20000x20000 took 67 s and
// gigabytes, one of 60000x60000 asked for 43 GB). "" when it may be.
std::string oversized_image(OIIO_NAMESPACE::ImageBuf& buf, const std::filesystem::path& path);

}  // namespace raygate
