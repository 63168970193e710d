#include "k40t_driver/sim/video/video_snapshot.h"

namespace k40t::sim::video {

bool is_image_mode(int code) {
  return code == 0 || code == 5 || code == 6 || code == 7;
}

}  // namespace k40t::sim::video
