#include "cfg_choices.h"

#include <QRegularExpression>

#include <k40t_driver/K40tConfig.h>

namespace k40t::rviz_panel {

// dynamic_reconfigure stores an enum as the Python repr of a dict:
// "{'enum': [{'name': 'palette_white_hot', 'type': 'int', 'value': 1, ..., 'description':
// 'white hot', ...}, ...], 'enum_description': '...'}".
QVector<Choice> cfgChoices(const char* parameter) {
  QVector<Choice> choices;
  for (const auto& description : k40t_driver::K40tConfig::__getParamDescriptions__()) {
    if (description->name != parameter) continue;
    static const QRegularExpression entry(R"('value': (-?\d+),[^{}]*'description': '([^']*)')");
    auto it = entry.globalMatch(QString::fromStdString(description->edit_method));
    while (it.hasNext()) {
      const auto match = it.next();
      choices.push_back({match.captured(1).toInt(), match.captured(2)});
    }
  }
  return choices;
}

}  // namespace k40t::rviz_panel
