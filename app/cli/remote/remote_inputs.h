// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The desk's files that a measurement run on a robot names (issue #44): `pipeline`'s frame files (a raw frame with
// its JSON sidecar), its --lens file and its --detector model files, and `bench dnn`'s --model files. Each one that
// exists at the desk is carried to the robot before the job runs (`job put`, into the job's inputs folder there), and
// its word in the command is replaced by where it lands. A path that exists only on the robot is left as it is: it is
// the robot's file.
#include <string>
#include <vector>

namespace bs::cli {

struct CarriedFile {
  std::string local_path;  // as the desk named it
  std::string name;        // where it goes in the job's inputs on the robot: "2/capture.raw" (its own name, in a
                           // numbered folder), unique within the job
};

struct CarriedCommand {
  std::vector<std::string> command;  // the words with each carried path replaced by its place on the robot
  std::vector<CarriedFile> files;    // in the order they are sent
};

// `robot_inputs_dir`: the job's inputs folder on the robot (its jobs folder / ID / inputs). `bench dnn` comes back
// as its grammar writes it (throws UsageError as it does); other commands come back unchanged.
CarriedCommand carry_desk_files(const std::vector<std::string>& command, const std::string& robot_inputs_dir);

}  // namespace bs::cli
