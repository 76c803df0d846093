// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The classes a "run here or on a robot" panel's header names without needing their definitions (Kernel Runner,
// Headroom, Sustained, Pipeline: the power sensor box and its recorder, the robot target, the job, the controller),
// declared once here so that each panel's header stays light and says only what is its own.

namespace bs::sensors {
class PowerRecorder;
}  // namespace bs::sensors

namespace bs::ui {
class PowerSensorBox;
class RemoteRun;
class RobotTarget;
class RunHereOrRobot;
}  // namespace bs::ui
