#pragma once
// A perspective camera with a thin lens (pbrt-v4's PerspectiveCamera with lensradius > 0; Pharr,
// Jakob and Humphreys, "Physically Based Rendering", 4th ed., section 5.2.3): depth of field.
//
// A thin lens of radius R focused at distance f brings every ray from one point of the plane in
// focus (perpendicular to the view direction, f along it) to one film position. So the ray of film
// position p leaves a point of the lens disk and passes through the point of the focus plane that
// the pinhole ray of p reaches. A point at depth d off that plane is seen through the whole lens
// as a disk on the film: on the focus plane the rays through it spread over a disk of radius
// R |d - f| / d, i.e. a circle of confusion of angular radius R |1/f - 1/d| (tangent units of the
// film; tests/camera/thin_lens_camera_test.cpp checks both).
#include "candela/camera/camera_frame.h"
#include "candela/camera/camera_model.h"
#include "candela/camera/camera_settings.h"
#include "candela/core/platform.h"
#include "candela/math/ray.h"
#include "candela/sampling/warps.h"

namespace candela {

class ThinLensCamera {
  public:
    // Valid settings (PerspectiveCamera's) with aperture_radius > 0.
    explicit ThinLensCamera(const CameraSettings& settings)
        : frame_(settings), screen_(settings, perspective_screen_window(settings)),
          lens_radius_(settings.aperture_radius), focus_distance_(resolved_focus_distance(settings)),
          near_(settings.near) {}

    // The ray of film position `film` through the lens point of `u_lens` in [0, 1)^2 (uniform on
    // the disk by the concentric map, as pbrt-v4 samples it).
    CANDELA_HD Ray generate_ray(const Vec2f& film, const Vec2f& u_lens) const {
        const Vec2f s = screen_(film);
        const Vec2f lens = sample_concentric_disk(u_lens) * lens_radius_;
        // In camera space the pinhole ray reaches the focus plane at (s f, f), the lens point is
        // (lens, 0); their difference is the direction, computed there rather than from two
        // world points so that a camera far from the origin loses no precision.
        const Vec3f d = normalize(frame_.to_world(s.x * focus_distance_ - lens.x, s.y * focus_distance_ - lens.y,
                                                  focus_distance_));
        const Vec3f o = frame_.position + frame_.right * lens.x + frame_.up * lens.y;
        return Ray{o + d * near_, d, 0.0f, kInfinity};
    }
    // The lens point is the sampler's next 2D request.
    CANDELA_HD Ray generate_ray(const Vec2f& film, Sampler& sampler) const {
        return generate_ray(film, sampler.next_vec2f());
    }

    float lens_radius() const { return lens_radius_; }
    float focus_distance() const { return focus_distance_; }

  private:
    CameraFrame frame_;
    FilmToScreen screen_;  // onto the plane at distance 1: tangents of the half angles
    float lens_radius_;
    float focus_distance_;
    float near_;
};
static_assert(CameraModel<ThinLensCamera>);

}  // namespace candela
