// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/robot_target.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QtConcurrent>

#include "common/reading_label.h"

namespace bs::ui {
namespace {
const QString kAddRobot = QStringLiteral("__add__");
}  // namespace

RobotTarget::RobotTarget(QWidget* parent)
    : QWidget(parent),
      box_(new QComboBox(this)),
      status_(reading_label(this)),
      check_button_(new QPushButton(tr("Check"), this)),
      platform_(new QLineEdit(this)),
      robot_row_(new QWidget(this)) {
  box_->setObjectName("targetBox");
  box_->setToolTip(
      tr("Where the kernel runs: this computer, or a robot reached with your SSH keys and config "
         "(batch mode: BenchScope never asks for or stores a password)"));
  box_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  box_->setMinimumContentsLength(16);
  status_->setObjectName("robotStatus");
  check_button_->setToolTip(tr("Contact the robot again: architecture, BenchScope there, backends, power sensors"));
  platform_->setObjectName("robotPlatform");
  platform_->setToolTip(tr("The platform the robot's results are stored under (its host name unless renamed)"));
  platform_->setPlaceholderText(tr("the robot's host name"));
  auto* row = new QHBoxLayout(robot_row_);
  row->setContentsMargins(0, 0, 0, 0);
  row->addWidget(new QLabel(tr("Platform"), robot_row_));
  row->addWidget(platform_, 1);
  row->addWidget(check_button_);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(box_);
  layout->addWidget(robot_row_);
  layout->addWidget(status_);
  connect(box_, &QComboBox::activated, this, [this] {
    if (box_->currentData().toString() == kAddRobot) add_robot();
  });
  connect(box_, &QComboBox::currentIndexChanged, this, &RobotTarget::on_choice);
  connect(check_button_, &QPushButton::clicked, this, &RobotTarget::recheck);
  connect(platform_, &QLineEdit::textEdited, this, [this] { platform_edited_ = true; });
  reload();
}

RobotTarget::~RobotTarget() {
  abort_->cancel();  // a check under way drops its connection rather than hold the window's closing up
  if (watcher_) watcher_->waitForFinished();
}

bool RobotTarget::is_robot() const {
  const QString d = box_->currentData().toString();
  return !d.isEmpty() && d != kAddRobot;
}

QString RobotTarget::robot_name() const { return is_robot() ? box_->currentData().toString() : QString(); }

remote::SshTarget RobotTarget::target() const {
  const std::string name = robot_name().toStdString();
  for (const remote::Robot& r : robots_)
    if (r.name == name) return r.target();
  remote::SshTarget t;
  t.destination = name;
  return t;
}

QString RobotTarget::not_ready(const QString& button) const {
  if (checking()) return tr("%1 is being checked; %2 again when it is ready").arg(robot_name(), button);
  if (!check_ || !check_->ok) return tr("%1 is not ready: see the message under \"Run on\"").arg(robot_name());
  return {};
}

QString RobotTarget::platform() const {
  const QString p = platform_->text().trimmed();
  if (!p.isEmpty()) return p;
  return check_ ? QString::fromStdString(check_->info.hostname) : QString();
}

void RobotTarget::remember_platform() {
  if (!is_robot()) return;
  try {
    remote::RobotList list;
    const std::string name = robot_name().toStdString();
    remote::Robot r = list.find(name) ? *list.find(name) : remote::Robot{};
    r.name = name;
    const remote::SshTarget t = target();
    r.config_file = t.config_file;
    r.remote_cli = t.remote_cli == "benchscope-cli" ? std::string() : t.remote_cli;
    r.platform = platform_->text().trimmed().toStdString();
    list.put(r);
  } catch (const std::exception&) {  // the list is a convenience; the run goes on under the name typed
  }
}

void RobotTarget::reload() {
  const QString keep = box_->currentData().toString();
  try {
    robots_ = remote::RobotList().all();
  } catch (const std::exception& e) {
    robots_.clear();
    status_->setText(tr("<small>Robots list: %1</small>").arg(QString::fromUtf8(e.what()).toHtmlEscaped()));
  }
  const QSignalBlocker block(box_);
  box_->clear();
  box_->addItem(tr("This computer"), QString());
  for (const remote::Robot& r : robots_) {
    const QString name = QString::fromStdString(r.name);
    QString label = name;
    if (!r.hostname.empty() && r.hostname != r.name)
      label += QStringLiteral(" (%1)").arg(QString::fromStdString(r.hostname));
    box_->addItem(tr("Robot: %1").arg(label), name);
    QString tip = r.last_contact.empty() ? tr("never contacted")
                                         : tr("last contact %1").arg(QString::fromStdString(r.last_contact));
    if (!r.runs.empty())
      tip += tr("\nlast run %1: %2 (%3)")
                 .arg(QString::fromStdString(r.runs.back().date), QString::fromStdString(r.runs.back().command),
                      QString::fromStdString(r.runs.back().outcome));
    box_->setItemData(box_->count() - 1, tip, Qt::ToolTipRole);
  }
  box_->addItem(tr("Add robot…"), kAddRobot);
  const int at = box_->findData(keep);
  box_->setCurrentIndex(at >= 0 && keep != kAddRobot ? at : 0);
  on_choice();
}

void RobotTarget::select(const QString& name) {
  const int at = box_->findData(name);
  if (at >= 0) box_->setCurrentIndex(at);
}

void RobotTarget::add_robot() {
  bool ok = false;
  const QString name = QInputDialog::getText(
      this, tr("Add robot"),
      tr("The robot's SSH destination: user@host, or a Host of ~/.ssh/config.\nBenchScope logs in with your keys "
         "and agent (ssh in batch mode) and never asks for a password."),
      QLineEdit::Normal, {}, &ok);
  if (!ok || name.trimmed().isEmpty()) {
    box_->setCurrentIndex(0);
    return;
  }
  try {
    remote::check_destination(name.trimmed().toStdString());
    remote::RobotList list;
    remote::Robot r;
    if (const remote::Robot* stored = list.find(name.trimmed().toStdString())) r = *stored;
    r.name = name.trimmed().toStdString();
    r.added = true;
    list.put(r);
  } catch (const std::exception& e) {
    QMessageBox::warning(this, tr("Add robot"), QString::fromUtf8(e.what()));
    box_->setCurrentIndex(0);
    return;
  }
  reload();
  select(name.trimmed());
}

void RobotTarget::on_choice() {
  const bool robot = is_robot();
  robot_row_->setVisible(robot);
  status_->setVisible(robot);
  check_.reset();
  platform_edited_ = false;
  platform_->clear();
  if (robot) {
    for (const remote::Robot& r : robots_)
      if (r.name == robot_name().toStdString() && !r.platform.empty()) {
        platform_->setText(QString::fromStdString(r.platform));
        platform_edited_ = true;  // the user's own name, kept
      }
    recheck();
  }
  emit changed();
}

void RobotTarget::recheck() {
  if (!is_robot() || watcher_) return;
  const remote::SshTarget t = target();
  checking_name_ = robot_name();
  check_.reset();
  check_button_->setEnabled(false);
  status_->setText(tr("<small>Contacting %1…</small>").arg(checking_name_.toHtmlEscaped()));
  watcher_ = new QFutureWatcher<remote::RobotCheck>(this);
  connect(watcher_, &QFutureWatcher<remote::RobotCheck>::finished, this, [this] {
    const remote::RobotCheck c = watcher_->result();
    watcher_->deleteLater();
    watcher_ = nullptr;
    check_button_->setEnabled(true);
    try {
      remote::RobotList().record_check(checking_name_.toStdString(), c, target());
    } catch (const std::exception&) {  // a read-only config folder: the check itself still counts
    }
    if (checking_name_ != robot_name()) {  // the user chose another target meanwhile
      recheck();
      return;
    }
    check_ = c;
    if (c.ok) {
      const remote::RobotInfo& i = c.info;
      QStringList backends, sensors;
      for (const remote::RobotBackend& b : i.backends)
        backends << QStringLiteral("%1 (%2)").arg(QString::fromStdString(b.label), QString::fromStdString(b.device));
      for (const remote::RobotSensor& x : i.sensors)
        if (x.readable) sensors << QString::fromStdString(x.id);
      status_->setText(
          tr("<small>%1 · %2%3 · BenchScope %4<br>backends: %5<br>power sensors: %6</small>")
              .arg(QString::fromStdString(i.hostname).toHtmlEscaped(), QString::fromStdString(i.arch).toHtmlEscaped(),
                   i.os.empty() ? QString() : " · " + QString::fromStdString(i.os).toHtmlEscaped(),
                   QString::fromStdString(i.cli_version).toHtmlEscaped(),
                   backends.join(QStringLiteral("; ")).toHtmlEscaped(),
                   sensors.isEmpty() ? tr("none readable") : sensors.join(QStringLiteral(", ")).toHtmlEscaped()));
      status_->setStyleSheet({});
      if (!platform_edited_) platform_->setText(QString::fromStdString(i.hostname));
    } else {
      status_->setText(QStringLiteral("<small>%1%2</small>")
                           .arg(QString::fromStdString(c.problem).toHtmlEscaped(),
                                c.fix.empty() ? QString()
                                              : tr("<br>To install it, run at this desk:<br><tt>%1</tt>")
                                                    .arg(QString::fromStdString(c.fix).toHtmlEscaped())));
      status_->setStyleSheet(QStringLiteral("color: #b00020;"));
    }
    emit changed();
  });
  watcher_->setFuture(QtConcurrent::run([t, abort = abort_] {
    try {
      return remote::check_robot(t, remote::JobControl{nullptr, abort.get()});
    } catch (const std::exception& e) {
      remote::RobotCheck c;
      c.problem = e.what();
      return c;
    }
  }));
  emit changed();
}

}  // namespace bs::ui
