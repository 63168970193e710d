// Placeholder until the thermal message structs land on main.
#include "k40t_driver/sim/request_handlers.h"

namespace k40t::sim {
void add_thermal_handlers(std::vector<HandlerEntry>&) {}
}  // namespace k40t::sim
