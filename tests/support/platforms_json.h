// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reading `benchscope-cli platforms --json` back in the CLI tests.
#include <QByteArray>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>

namespace bs::test {

// The platform the command recommends; empty when it recommends none.
inline QString recommended(const QByteArray& platforms_json) {
  for (const auto v : QJsonDocument::fromJson(platforms_json).object()["platforms"].toArray())
    if (v.toObject()["recommended"].toBool()) return v.toObject()["platform"].toString();
  return {};
}

}  // namespace bs::test
