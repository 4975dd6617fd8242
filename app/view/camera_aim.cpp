#include "app/view/camera_aim.h"

#include "view/scene_view.h"

namespace skylit::app::view {

skylit::view::CameraTarget CameraAim::at(const std::optional<shade::TrackedAircraft>& aircraft, std::size_t track,
                                         double unix_seconds, double exaggeration) {
  if (aircraft)
    if (const auto pose = aircraft->pose_at(track, unix_seconds))
      last_ = skylit::view::CameraTarget{pose->position, pose->attitude.heading_deg};
  if (!last_) return skylit::view::field_centre_target(field_, exaggeration);
  skylit::view::CameraTarget aim = *last_;
  aim.position.z *= exaggeration;
  return aim;
}

}  // namespace skylit::app::view
