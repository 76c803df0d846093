// SPDX-License-Identifier: GPL-3.0-or-later
// Resource lookup: $BENCHSCOPE_RESOURCE_DIR first, then an installed layout beside the executable, then the source
// tree; a missing resource names every directory searched.
#include <QTest>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "util/resources.h"

namespace fs = std::filesystem;

class TestResources : public QObject {
  Q_OBJECT
 private slots:
  void source_tree_is_found_from_a_build_dir() {
    ::unsetenv("BENCHSCOPE_RESOURCE_DIR");
    const fs::path p = bs::find_resource("devices/devices.json");
    QCOMPARE(fs::weakly_canonical(p),
             fs::weakly_canonical(fs::path(BENCHSCOPE_SOURCE_DIR) / "resources/devices/devices.json"));
    QVERIFY(fs::is_regular_file(bs::find_resource("figures/paper-2018.json")));
  }
  void environment_overrides() {
    const fs::path dir = fs::temp_directory_path() / ("bs-resources-" + std::to_string(::getpid()));
    fs::create_directories(dir / "devices");
    std::ofstream(dir / "devices/devices.json") << "{}";
    ::setenv("BENCHSCOPE_RESOURCE_DIR", dir.c_str(), 1);
    QCOMPARE(bs::find_resource("devices/devices.json"), fs::weakly_canonical(dir) / "devices/devices.json");
    // A file only the source tree has is still found there.
    QVERIFY(fs::is_regular_file(bs::find_resource("figures/paper-2018.json")));
    ::unsetenv("BENCHSCOPE_RESOURCE_DIR");
    fs::remove_all(dir);
  }
  void missing_resource_names_the_places_searched() {
    try {
      bs::find_resource("devices/no-such-file.json");
      QFAIL("found a file that does not exist");
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      QVERIFY2(what.find("devices/no-such-file.json") != std::string::npos, e.what());
      QVERIFY2(what.find(BENCHSCOPE_SOURCE_DIR) != std::string::npos, e.what());
      QVERIFY2(what.find("BENCHSCOPE_RESOURCE_DIR") != std::string::npos, e.what());
    }
  }
};

QTEST_APPLESS_MAIN(TestResources)
#include "test_resources.moc"
