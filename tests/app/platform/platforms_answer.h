// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What `benchscope-cli platforms` is asked and answers in the tests of this room: the paper's sample data it reads,
// and the platform its --json recommends.
#include <QByteArray>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>

namespace bs::test {

inline const QString kPaper = BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018";

// The recommended platform's name in `platforms --json`'s output, or an empty string when none is recommended.
inline QString recommended(const QByteArray& json) {
  for (const auto v : QJsonDocument::fromJson(json).object()["platforms"].toArray())
    if (v.toObject()["recommended"].toBool()) return v.toObject()["platform"].toString();
  return {};
}

}  // namespace bs::test
