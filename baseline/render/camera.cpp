// Building the camera basis from an NFF view.
#include "render/camera.h"

#include <cmath>
#include <numbers>
#include <string>

#include "render/world.h"

namespace raygate::render {
namespace {

// Limits that keep a typo in `resolution` from exhausting memory.
// The side is the reader's limit (nff::kMaxResolutionSide), checked again for a scene built in
// code; the pixel count is the camera's own.
constexpr int kMaxImageSide = nff::kMaxResolutionSide;
constexpr double kMaxImagePixels = 67108864.0;  // 2^26, e.g. 8192 x 8192

void require(bool condition, const std::string& what) {
  if (!condition) throw SceneError("unusable view: " + what);
}

}  // namespace

Vec3 Camera::direction_at(double x, double y) const {
  const double horizontal = 2.0 * x / width - 1.0;
  const double vertical = 1.0 - 2.0 * y / height;
  return normalize(forward + right_span * horizontal + up_span * vertical);
}

Camera make_camera(const nff::View& view) {
  require(view.width > 0 && view.height > 0, "resolution must be positive");
  require(view.width <= kMaxImageSide && view.height <= kMaxImageSide &&
              double(view.width) * double(view.height) <= kMaxImagePixels,
          "resolution too large (at most " + std::to_string(kMaxImageSide) +
              " per side and 2^26 pixels)");
  require(std::isfinite(view.angle_degrees) && view.angle_degrees > 0.0 &&
              view.angle_degrees < 180.0,
          "angle must be between 0 and 180 degrees");
  require(std::isfinite(view.hither), "hither must be finite");
  const Vec3 to_target = view.at - view.from;
  const double distance = length(to_target);
  require(std::isfinite(distance) && distance > 0.0, "'from' and 'at' must differ");

  Camera camera;
  camera.eye = view.from;
  camera.forward = to_target / distance;
  const Vec3 up_perpendicular = view.up - camera.forward * dot(view.up, camera.forward);
  const double up_length = length(up_perpendicular);
  // A relative test: an `up` within ~1e-9 rad of the view direction gives no usable basis.
  require(std::isfinite(up_length) && up_length > 1e-9 * length(view.up),
          "'up' must not be parallel to the view direction");
  camera.up = up_perpendicular / up_length;
  camera.right = normalize(cross(camera.forward, camera.up));

  const double half_angle = view.angle_degrees * std::numbers::pi / 360.0;
  const double half_width = std::tan(half_angle);
  // Square pixels: `angle` spans the width; the height follows the aspect ratio.
  const double half_height = half_width * view.height / view.width;
  camera.right_span = camera.right * half_width;
  camera.up_span = camera.up * half_height;
  camera.hither = view.hither > 0.0 ? view.hither : 0.0;
  camera.width = view.width;
  camera.height = view.height;
  return camera;
}

}  // namespace raygate::render
