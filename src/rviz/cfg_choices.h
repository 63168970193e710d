// The choices of an enum parameter of the driver's dynamic_reconfigure config (cfg/K40t.cfg),
// read from the generated K40tConfig's parameter descriptions: the panel's combo boxes offer
// exactly what the driver accepts, with no list of its own to keep in step.
#pragma once

#include <QString>
#include <QVector>

namespace k40t::rviz_panel {

struct Choice {
  int value;
  QString label;  // the constant's description in K40t.cfg, e.g. "iron red"
};

// The enum constants of `parameter` ("palette", "image_mode", "camera_mode"); empty if it has none.
QVector<Choice> cfgChoices(const char* parameter);

}  // namespace k40t::rviz_panel
