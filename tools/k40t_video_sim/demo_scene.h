// The temperature scene of the standalone stream (k40t_video_sim runs without the pod model):
// a cold sky, 20 degC ground with a gentle texture, a hot spot and a cold patch on the ground.
#pragma once

#include "k40t_driver/sim/video/video_snapshot.h"

namespace k40t::tools {

double demo_scene_temperature(const sim::video::WorldDirection& direction);

}  // namespace k40t::tools
