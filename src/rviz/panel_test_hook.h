// Scripted user input for the panel's end-to-end test (test/ros/panel.test), off unless the
// environment variable K40T_PANEL_TEST_COMMANDS names a file. The test appends command lines to
// that file; each is carried out on the GUI thread as real input events (QTest mouse and key
// events sent to the named widget, so the widgets' own handlers run, exactly as for a user), and
// answered with one line appended to FILE.replies: "N ok [text]" or "N error what", N counting
// the commands from 1.
//   click NAME                 left click in the middle
//   press NAME [RIGHT UP]      left button down (at RIGHT, UP in -1..1 from the middle)
//   release NAME               left button up
//   key NAME KEY               a key click (Qt key names: PgUp, Up, Left, End...)
//   keypress NAME KEY          a key held down ... keyrelease NAME KEY   ... and let go
//   choose NAME TEXT           a combo box stepped with the arrow keys until it shows TEXT
//   type NAME TEXT             a spin box's or line edit's text selected, TEXT typed, Enter
//   text NAME                  replies with the label's plain text (or the line edit's text)
//   grab NAME PATH             saves a picture of the widget (the panel: "PodPanel") as PNG
#pragma once

#include <QFile>
#include <QObject>
#include <QString>
#include <QTimer>
#include <memory>

class QWidget;

namespace k40t::rviz_panel {

class PanelTestHook : public QObject {
  Q_OBJECT
 public:
  // The hook if K40T_PANEL_TEST_COMMANDS is set, else null.
  static std::unique_ptr<PanelTestHook> fromEnvironment(QWidget* panel);
  PanelTestHook(QWidget* panel, const QString& path);

 private:
  void poll();
  QString run(const QString& line);  // "ok [text]" or "error what"

  QWidget* panel_;
  QString path_;
  qint64 offset_ = 0;
  QString partial_;
  int count_ = 0;
  QTimer timer_;
};

}  // namespace k40t::rviz_panel
