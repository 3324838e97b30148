// The pinhole camera of spd-spec.md §1.3. Image-plane positions are in pixel units with (0, 0)
// at the top-left corner of the top-left pixel and (W, H) at the bottom-right corner, so a
// pixel centre is (i + 0.5, j + 0.5) and the SPD corner rays are at integer positions.
#pragma once

#include "geom/ray.h"
#include "nff/scene.h"

namespace raygate::render {

struct Camera {
  Vec3 eye;
  Vec3 forward;     // unit
  Vec3 right;       // unit, forward x up (right-handed)
  Vec3 up;          // unit, `up` made perpendicular to forward
  Vec3 right_span;  // right * tan(angle/2): from the image centre to the right edge
  Vec3 up_span;     // up * tan(angle/2) * H/W: from the centre to the top edge
  double hither = 0.0;
  int width = 0;
  int height = 0;

  // Unit direction through image-plane position (x, y).
  Vec3 direction_at(double x, double y) const;

  // The eye ray through (x, y), and its smallest allowed distance: points nearer than
  // `hither` along the view direction are clipped.
  Ray ray_at(double x, double y) const { return {eye, direction_at(x, y)}; }
  double t_min(const Ray& eye_ray) const {
    return hither > 0.0 ? hither / dot(eye_ray.direction, forward) : 0.0;
  }
};

// Throws SceneError (render/world.h) for a view no image can come from: from == at, up
// parallel to the view direction, angle outside (0, 180), non-positive resolution.
Camera make_camera(const nff::View& view);

}  // namespace raygate::render
