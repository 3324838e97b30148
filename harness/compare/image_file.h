// An image file read as it is now. OpenImageIO's shared ImageCache keeps what it learned of a
// file by name; a file rewritten in place within one process (another size) was read with the
// spec it had before, past the end of the new buffer (a crash found blessing a run's images
// after their first bless). Every image raygate decodes is opened through here.
#pragma once

#include <OpenImageIO/imagebuf.h>

#include <filesystem>

namespace raygate {

OIIO_NAMESPACE::ImageBuf current_image(const std::filesystem::path& path);

}  // namespace raygate
