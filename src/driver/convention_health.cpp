#include "k40t_driver/driver/convention_health.h"

namespace k40t::driver {

HealthCheck conventions_health(const std::vector<ConventionStatus>& readings) {
  HealthCheck check;
  std::string contradicted;
  for (const ConventionStatus& r : readings) {
    // "yaw_sign": "right (default)", and the contradiction beside it when there is one.
    check.add(r.name, r.value + " (" + r.source + ")");
    if (r.contradiction.empty()) continue;
    check.add(r.name + " contradicted", r.contradiction);
    contradicted += (contradicted.empty() ? "" : ", ") + r.name;
  }
  if (contradicted.empty()) {
    check.set(HealthLevel::kOk, "no reading contradicted by the pod's traffic");
  } else {
    check.set(HealthLevel::kWarn, "the pod's traffic contradicts " + contradicted +
                                      " (see docs/protocol/decisions.md#conventions)");
  }
  return check;
}

}  // namespace k40t::driver
