#pragma once
// An orthographic camera: parallel rays along the view direction, from a film `ortho_height`
// scene units high centred on `position` (pbrt-v4's OrthographicCamera, with the screen window
// given in scene units). With aperture_radius > 0 it has a thin lens focused at focus_distance,
// as pbrt-v4's: the ray of a film point leaves a lens point around it and passes through the point
// of the focus plane straight ahead of it, so the focus plane is sharp and the rest blurs by
// R |d - f| / f in scene units (the same blur at every depth scale, there being no perspective).
//
// Unlike pbrt-v4 (and pbrt-v3, issue mmp/pbrt-v3#315), the lens is centred on the film point, not
// on the camera's axis: there every ray starts within R of the axis, so away from the image's
// centre the rays are oblique and the view off the focus plane is no longer orthographic.
#include "candela/camera/camera_frame.h"
#include "candela/camera/camera_model.h"
#include "candela/camera/camera_settings.h"
#include "candela/core/platform.h"
#include "candela/math/ray.h"
#include "candela/sampling/warps.h"

namespace candela {

class OrthographicCamera {
  public:
    // Valid settings with ortho_height > 0.
    explicit OrthographicCamera(const CameraSettings& settings)
        : frame_(settings), screen_(settings, orthographic_screen_window(settings)),
          lens_radius_(settings.aperture_radius), focus_distance_(resolved_focus_distance(settings)),
          near_(settings.near) {}

    // Without a lens: the ray from the film point along the view direction.
    CANDELA_HD Ray generate_ray(const Vec2f& film) const {
        const Vec2f s = screen_(film);
        const Vec3f o = frame_.position + frame_.right * s.x + frame_.up * s.y;
        return Ray{o + frame_.forward * near_, frame_.forward, 0.0f, kInfinity};
    }
    // With the lens (lens_radius() > 0): through the lens point of `u_lens` around the film point,
    // towards the focus point focus_distance ahead of it.
    CANDELA_HD Ray generate_ray(const Vec2f& film, const Vec2f& u_lens) const {
        const Vec2f s = screen_(film);
        const Vec2f lens = sample_concentric_disk(u_lens) * lens_radius_;
        const Vec3f d = normalize(frame_.to_world(-lens.x, -lens.y, focus_distance_));
        const Vec3f o = frame_.position + frame_.right * (s.x + lens.x) + frame_.up * (s.y + lens.y);
        return Ray{o + d * near_, d, 0.0f, kInfinity};
    }
    // The lens point is the sampler's next 2D request, taken only when there is a lens (a property
    // of the scene, so every sample asks the same requests).
    CANDELA_HD Ray generate_ray(const Vec2f& film, Sampler& sampler) const {
        return lens_radius_ > 0.0f ? generate_ray(film, sampler.next_vec2f()) : generate_ray(film);
    }

    float lens_radius() const { return lens_radius_; }

  private:
    CameraFrame frame_;
    FilmToScreen screen_;  // in scene units
    float lens_radius_;
    float focus_distance_;
    float near_;
};
static_assert(CameraModel<OrthographicCamera>);

}  // namespace candela
