// What the live pod model shows on its video stream (k40t_sim --rtsp-port): image mode and
// stream resolution (0x000003), palette and thermal digital zoom, the telephoto's hybrid zoom as
// it moves, where the boresight points, and the model's world as the thermal scene.
#pragma once

#include "k40t_driver/sim/pod_model.h"
#include "k40t_driver/sim/video/video_snapshot.h"

namespace k40t::sim::video {

// Called under the model's lock; the snapshot holds a copy of the world, so it stays valid after.
VideoSnapshot snapshot_of(const PodModel& model);

}  // namespace k40t::sim::video
