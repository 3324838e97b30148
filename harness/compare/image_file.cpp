#include "compare/image_file.h"

#include <OpenImageIO/imagecache.h>

namespace raygate {

OIIO_NAMESPACE::ImageBuf current_image(const std::filesystem::path& path) {
  OIIO_NAMESPACE::ImageCache::create(true)->invalidate(OIIO_NAMESPACE::ustring(path.string()));
  return OIIO_NAMESPACE::ImageBuf(path.string());
}

}  // namespace raygate
