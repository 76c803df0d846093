// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A person at the keyboard, for scenario tests of the real main window (issue #43): input goes in through the window
// system (QTest's QWindow overloads: QWindowSystemInterface, as X events arrive), so a window that lies under a modal
// dialog gets nothing, exactly as a person's clicks would get nothing. Modal dialogs are answered from the running
// event loop: a timer looks at QApplication::activeModalWidget() and answers the dialog the scenario expects next,
// with clicks and keys. Nothing here calls a slot behind a dialog.
//
// Waiting counts polls (a qWait of a few milliseconds each), never reads a clock (scripts/check-tests).
#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>
#include <QProcess>
#include <QProgressDialog>
#include <QPushButton>
#include <QTest>
#include <QTimer>
#include <QWidget>
#include <QWindow>
#include <functional>
#include <utility>
#include <vector>

namespace bs::test {

// ---- input as a person gives it ----------------------------------------------------------------------------------

inline QString plain(QString text) { return text.remove('&'); }

// A click on `w` (at `at`, its own coordinates; its centre by default), delivered to w's top-level window.
inline void click(QWidget* w, Qt::MouseButton button = Qt::LeftButton, Qt::KeyboardModifiers mods = {},
                  QPoint at = QPoint(-1, -1)) {
  QWidget* top = w->window();
  if (at.x() < 0) at = w->rect().center();
  QTest::mouseClick(top->windowHandle(), button, mods, w->mapTo(top, at));
}

// A key on the window of `w`; the window's focus widget gets it (or a shortcut of the window). The window is made
// the active one first, as a person's click into it would under a window manager (Xvfb has none, so a window stays
// inactive after a dialog closes, and Qt gives window shortcuts only to the active window).
inline void key(QWidget* w, Qt::Key k, Qt::KeyboardModifiers mods = {}) {
  QWidget* top = w->window();
  if (QApplication::activeWindow() != top) {
    top->activateWindow();
    for (int i = 0; i < 50 && QApplication::activeWindow() != top; ++i) QTest::qWait(10);
  }
  QTest::keyClick(top->windowHandle(), k, mods);
}

// Text typed into the window of `w` (its focus widget), one key per character (ASCII: paths, names, numbers).
inline void type(QWidget* w, const QString& text) {
  for (const QChar c : text) QTest::keyClick(w->window()->windowHandle(), c.toLatin1());
}

// Clicks into a line edit (or an editable combo box), selects what it holds and types `text` over it.
inline void retype(QWidget* field, const QString& text) {
  click(field);
  key(field, Qt::Key_A, Qt::ControlModifier);
  type(field, text);
}

// Runs the event loop `polls` times for a few milliseconds each, until `done` holds. Returns whether it did.
inline bool wait_until(const std::function<bool()>& done, int polls = 1500) {
  for (int i = 0; i < polls; ++i) {
    if (done()) return true;
    QTest::qWait(20);
  }
  return done();
}

// A scenario step done by a helper that returns "" when it worked, else what went wrong in the person's words
// (open_paper_window, export_report, pick_next_entry): the test fails with those words.
#define BS_STEP(step)                                                 \
  do {                                                                \
    const QString bs_step_problem = (step);                           \
    QVERIFY2(bs_step_problem.isEmpty(), qPrintable(bs_step_problem)); \
  } while (false)

// Clicks a combo box open and picks the entry below the current one with the keyboard, as a person does. The keys go
// to the open list itself (it has the keyboard while open): key() would first try to make it the active window,
// which a popup never becomes, and under load the list could close meanwhile. Returns an empty string, or what went
// wrong.
inline QString pick_next_entry(QComboBox* box) {
  click(box);
  if (!wait_until([] { return QApplication::activePopupWidget() != nullptr; }, 100)) return "the list did not open";
  const QPointer<QWidget> list = QApplication::activePopupWidget();
  QTest::keyClick(list->windowHandle(), Qt::Key_Down);
  if (!list || !list->isVisible()) return "the list closed before the person picked";
  QTest::keyClick(list->windowHandle(), Qt::Key_Return);
  return {};
}

// The button of `dialog` whose text (without '&') is `text`, or of the standard kind `which`.
inline QAbstractButton* button(QWidget* dialog, const QString& text) {
  for (QAbstractButton* b : dialog->findChildren<QAbstractButton*>())
    if (b->isVisible() && plain(b->text()) == text) return b;
  return nullptr;
}
inline QAbstractButton* button(QWidget* dialog, QDialogButtonBox::StandardButton which) {
  for (QDialogButtonBox* box : dialog->findChildren<QDialogButtonBox*>())
    if (QAbstractButton* b = box->button(which); b && b->isVisible()) return b;
  return nullptr;
}

// The field a form row is labelled with (QFormLayout sets the label's buddy), as a person finds it by its label.
template <typename T>
T* field(QWidget* parent, const QString& label) {
  for (QLabel* l : parent->findChildren<QLabel*>())
    if (plain(l->text()) == label && l->buddy())
      if (T* t = qobject_cast<T*>(l->buddy())) return t;
  return nullptr;
}

// The visible widget of type T under `parent` whose text (button, label, check box) is `text`.
template <typename T>
T* widget_with_text(QWidget* parent, const QString& text) {
  for (T* w : parent->findChildren<T*>())
    if (w->isVisible() && plain(w->text()) == text) return w;
  return nullptr;
}

// A file chosen in Qt's own file dialog (no native dialog under Xvfb): the path typed into its name field, Enter.
inline void choose_file(QWidget* dialog, const QString& path) {
  auto* name = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"));
  if (!name) return;
  retype(name, path);
  key(name, Qt::Key_Return);
}

// Several files of one folder: the folder typed and entered first, then the names in quotes, as Qt's dialog takes them.
inline void choose_files(QWidget* dialog, const QString& folder, const QStringList& names) {
  auto* name = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"));
  if (!name) return;
  retype(name, folder + '/');
  key(name, Qt::Key_Return);
  QStringList quoted;
  for (const QString& n : names) quoted << '"' + n + '"';
  retype(name, quoted.join(' '));
  key(name, Qt::Key_Return);
}

// ---- modal dialogs answered from the event loop -------------------------------------------------------------------

// The scenario says which dialogs it expects, in order, and what the person does in each. A timer (every 20 ms, from
// the running event loop, nested dialog loops included) looks at the active modal widget:
//  - the expected dialog on top: it is answered (clicks, keys); once it closes, the next one is expected;
//  - the expected dialog open but under another modal dialog (e.g. a progress dialog shown after it): the person
//    clicks it anyway (the window system drops the input) and that is recorded as `blocked`; after
//    `kPatience` tries the person gives up the only way left, Cancel on the dialog on top, as a person would;
//  - a modal dialog nobody expected (not a progress dialog): recorded in `unexpected` and closed with Escape after
//    a while, so that a broken scenario fails instead of hanging.
class ModalAnswerer : public QObject {
 public:
  using Match = std::function<bool(QWidget*)>;
  using Answer = std::function<void(QWidget*)>;
  static constexpr int kPatience = 50;  // polls (about a second) before a blocked or stray dialog is given up
  // A person reads a dialog before answering it (about 0.6 s): in that time whatever else opens (a progress
  // dialog after 300 ms) opens, as it would for a person. Answering at once would hide what covers the dialog.
  static constexpr int kReading = 30;

  explicit ModalAnswerer(QObject* parent = nullptr) : QObject(parent) {
    timer_.setInterval(20);
    connect(&timer_, &QTimer::timeout, this, [this] { poll(); });
    timer_.start();
  }

  void expect(const QString& what, Match is_it, Answer answer) {
    pending_.push_back({what, std::move(is_it), std::move(answer)});
  }
  // A dialog whose window title starts with `title`.
  static Match titled(const QString& title) {
    return [title](QWidget* w) { return w->windowTitle().startsWith(title); };
  }
  bool done() const { return pending_.empty(); }
  QString next() const { return pending_.empty() ? QString() : pending_.front().what; }
  QStringList answered, blocked, unexpected, gave_up;
  QStringList seen;  // every modal dialog that was on top, by title, in order (for failure messages)

  QString report() const {
    return QStringLiteral(
               "answered [%1]; blocked [%2]; gave up [%3]; unexpected [%4]; modal dialogs seen [%5]; still "
               "expected: %6")
        .arg(answered.join(", "), blocked.join(", "), gave_up.join(", "), unexpected.join(", "), seen.join(", "),
             next());
  }

 private:
  struct Expected {
    QString what;
    Match is_it;
    Answer answer;
  };

  static QWidget* find_open(const Match& is_it) {
    for (QWidget* w : QApplication::topLevelWidgets())
      if (w->isVisible() && is_it(w)) return w;
    return nullptr;
  }

  void poll() {
    if (busy_) return;  // an answer's own clicks run the event loop (a nested dialog): one poll at a time
    busy_ = true;
    QWidget* top = QApplication::activeModalWidget();
    if (top && (seen.isEmpty() || seen.back() != top->windowTitle())) seen << top->windowTitle();
    if (!pending_.empty()) {
      Expected& e = pending_.front();
      if (has_answered_ && (!answering_ || !answering_->isVisible())) {  // the dialog answered is gone: next one
        answered << e.what;
        pending_.erase(pending_.begin());
        answering_ = nullptr;
        has_answered_ = false;
        tries_ = 0;
        busy_ = false;
        return;
      }
      QWidget* target = answering_ ? answering_.data() : find_open(e.is_it);
      if (target && !answering_ && ++reading_ <= kReading) {  // still reading it
        busy_ = false;
        return;
      }
      if (target) {
        reading_ = 0;
        const bool on_top = top == target;
        if (!on_top && tries_ == 0)
          blocked << QStringLiteral("%1 under %2").arg(e.what, top ? top->windowTitle() : "?");
        if (!on_top && ++tries_ > kPatience && top) {
          gave_up << QStringLiteral("%1 (Cancel on %2)").arg(e.what, top->windowTitle());
          if (QAbstractButton* cancel = button(top, QStringLiteral("Cancel"))) click(cancel);
          tries_ = 0;
          busy_ = false;
          return;
        }
        answering_ = target;
        has_answered_ = true;
        e.answer(target);  // dropped by the window system while the dialog is blocked: tried again next poll
        busy_ = false;
        return;
      }
    }
    // Nothing expected is open: a modal dialog on top that nobody expects is closed after a while.
    if (top && !qobject_cast<QProgressDialog*>(top)) {
      if (++stray_ > kPatience) {
        unexpected << top->windowTitle();
        key(top, Qt::Key_Escape);
        stray_ = 0;
      }
    } else {
      stray_ = 0;
    }
    busy_ = false;
  }

  QTimer timer_;
  std::vector<Expected> pending_;
  QPointer<QWidget> answering_;
  int tries_ = 0, stray_ = 0, reading_ = 0;
  bool busy_ = false, has_answered_ = false;
};

// ---- reading outputs back --------------------------------------------------------------------------------------

// One page of a PDF as text (pdftotext, poppler-utils), as a reader would copy it.
inline QString pdf_page_text(const QString& pdf, int page) {
  QProcess p;
  p.start(QStringLiteral("pdftotext"),
          {QStringLiteral("-f"), QString::number(page), QStringLiteral("-l"), QString::number(page),
           QStringLiteral("-enc"), QStringLiteral("UTF-8"), pdf, QStringLiteral("-")});
  if (!p.waitForFinished(60000)) return {};
  return QString::fromUtf8(p.readAllStandardOutput());
}

// Screenshots of what a scenario touched, when BENCHSCOPE_SCENARIO_SHOTS names a folder (for a person to look at).
inline void screenshot(QWidget* w, const QString& name) {
  const QString dir = qEnvironmentVariable("BENCHSCOPE_SCENARIO_SHOTS");
  if (dir.isEmpty()) return;
  w->grab().save(dir + '/' + name + ".png");
}

}  // namespace bs::test
