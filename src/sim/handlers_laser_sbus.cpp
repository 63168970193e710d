// Placeholder until the laser_sbus message structs land on main.
#include "k40t_driver/sim/request_handlers.h"

namespace k40t::sim {
void add_laser_sbus_handlers(std::vector<HandlerEntry>&) {}
}  // namespace k40t::sim
