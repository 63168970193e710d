#include "panel_test_hook.h"

#include <QAbstractSpinBox>
#include <QComboBox>
#include <QKeySequence>
#include <QLabel>
#include <QLineEdit>
#include <QPixmap>
#include <QTest>
#include <QTextDocument>
#include <QWidget>

namespace k40t::rviz_panel {
namespace {

constexpr int kPollMs = 50;

// A reply: ok (with an optional text) or an error.
struct Outcome {
  bool ok;
  QString text;
};

Qt::Key keyNamed(const QString& name) {
  const QKeySequence sequence = QKeySequence::fromString(name);
  return sequence.isEmpty() ? Qt::Key_unknown
                            : static_cast<Qt::Key>(sequence[0] & ~Qt::KeyboardModifierMask);
}

QPoint pointAt(QWidget* w, const QStringList& words, int first) {
  const QPoint middle = w->rect().center();
  if (words.size() < first + 2) return middle;
  const double right = words[first].toDouble();
  const double up = words[first + 1].toDouble();
  return middle +
         QPoint(static_cast<int>(right * w->width() / 2), static_cast<int>(-up * w->height() / 2));
}

Outcome choose(QComboBox* box, const QString& wanted) {
  const int target = box->findText(wanted);
  if (target < 0) return {false, "no item '" + wanted + "'"};
  for (int step = 0; step <= box->count() && box->currentIndex() != target; ++step) {
    QTest::keyClick(box, box->currentIndex() < target ? Qt::Key_Down : Qt::Key_Up);
  }
  return {box->currentIndex() == target, box->currentText()};
}

Outcome carryOut(QWidget* panel, const QStringList& words) {
  const QString& verb = words[0];
  QWidget* w = words[1] == panel->objectName() ? panel : panel->findChild<QWidget*>(words[1]);
  if (!w) return {false, "no widget named " + words[1]};
  if (!w->isVisible()) return {false, words[1] + " is not visible"};
  const QString rest = words.mid(2).join(' ');
  if (verb == "click") {
    QTest::mouseClick(w, Qt::LeftButton);
  } else if (verb == "press") {
    QTest::mousePress(w, Qt::LeftButton, Qt::NoModifier, pointAt(w, words, 2));
  } else if (verb == "release") {
    QTest::mouseRelease(w, Qt::LeftButton, Qt::NoModifier, pointAt(w, words, 2));
  } else if (verb == "key" || verb == "keypress" || verb == "keyrelease") {
    const Qt::Key key = keyNamed(rest);
    if (key == Qt::Key_unknown) return {false, "unknown key " + rest};
    if (verb == "key") QTest::keyClick(w, key);
    if (verb == "keypress") QTest::keyPress(w, key);
    if (verb == "keyrelease") QTest::keyRelease(w, key);
  } else if (verb == "choose") {
    auto* box = qobject_cast<QComboBox*>(w);
    if (!box) return {false, words[1] + " is not a combo box"};
    return choose(box, rest);
  } else if (verb == "type") {
    if (auto* box = qobject_cast<QAbstractSpinBox*>(w)) {
      box->selectAll();
    } else if (auto* edit = qobject_cast<QLineEdit*>(w)) {
      edit->selectAll();
    } else {
      return {false, words[1] + " is not a spin box or a line edit"};
    }
    QTest::keyClicks(w, rest);
    QTest::keyClick(w, Qt::Key_Return);
  } else if (verb == "text") {
    if (auto* edit = qobject_cast<QLineEdit*>(w)) return {true, edit->text()};
    auto* label = qobject_cast<QLabel*>(w);
    if (!label) return {false, words[1] + " is not a label or a line edit"};
    QTextDocument html;
    html.setHtml(label->text());
    return {true, html.toPlainText().simplified()};
  } else if (verb == "grab") {
    if (!w->grab().save(rest, "PNG")) return {false, "cannot write " + rest};
  } else {
    return {false, "unknown command " + verb};
  }
  return {true, {}};
}

}  // namespace

std::unique_ptr<PanelTestHook> PanelTestHook::fromEnvironment(QWidget* panel) {
  const QString path = qEnvironmentVariable("K40T_PANEL_TEST_COMMANDS");
  if (path.isEmpty()) return nullptr;
  return std::make_unique<PanelTestHook>(panel, path);
}

PanelTestHook::PanelTestHook(QWidget* panel, const QString& path) : panel_(panel), path_(path) {
  connect(&timer_, &QTimer::timeout, this, &PanelTestHook::poll);
  timer_.start(kPollMs);
}

void PanelTestHook::poll() {
  QFile commands(path_);
  if (!commands.open(QIODevice::ReadOnly) || !commands.seek(offset_)) return;
  const QByteArray fresh = commands.readAll();
  offset_ += fresh.size();
  partial_ += QString::fromUtf8(fresh);
  while (partial_.contains('\n')) {
    const int end = partial_.indexOf('\n');
    const QString line = partial_.left(end).trimmed();
    partial_.remove(0, end + 1);
    if (line.isEmpty()) continue;
    const QString reply = QString("%1 %2").arg(++count_).arg(run(line));
    QFile replies(path_ + ".replies");
    if (replies.open(QIODevice::Append)) replies.write((reply.trimmed() + '\n').toUtf8());
  }
}

QString PanelTestHook::run(const QString& line) {
  const QStringList words = line.split(' ', Qt::SkipEmptyParts);
  if (words.size() < 2) return "error a command needs a widget name: " + line;
  const Outcome outcome = carryOut(panel_, words);
  return (outcome.ok ? "ok " : "error ") + outcome.text;
}

}  // namespace k40t::rviz_panel
