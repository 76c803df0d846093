// SPDX-License-Identifier: GPL-3.0-or-later
// Lazy loading of power traces (schema 6, issue #19 "Scale"): a trace read as summary first and samples later,
// chunk by chunk, gives the same numbers as the eager read and as the trace that was imported; the summary cached
// at import equals the one computed from the loaded samples; a schema 5 workspace's one-BLOB trace is converted;
// loading reports progress and can be cancelled.
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <limits>

#include "analysis/power/power.h"
#include "analysis/power/power_stats.h"
#include "analysis/power/trace_summary.h"
#include "store/power_samples.h"
#include "workspace_test_support.h"

using bs::test::RawDb;
using bs::test::same_bits;

namespace {

// Irregular timestamps, a spike, missing samples, two channels; longer than three chunks so chunk boundaries, a
// partial last chunk and the overview's decimation are all exercised.
bs::PowerTrace make_trace(std::size_t n) {
  bs::PowerTrace t;
  t.platform = "Bench";
  t.label = "long log";
  t.supply_voltage_v = 16.0;
  t.time_s.resize(n);
  bs::PowerChannel i{"I", bs::PowerQuantity::Current, std::vector<double>(n)};
  bs::PowerChannel v{"V", bs::PowerQuantity::Voltage, std::vector<double>(n)};
  double time = 0;
  for (std::size_t k = 0; k < n; ++k) {
    time += 0.00025 * (1.0 + 0.1 * static_cast<double>(k % 7));
    t.time_s[k] = time;
    i.values[k] = 0.6 + 1.8 * ((k / 50000) % 2) + 0.001 * static_cast<double>(k % 97) + (k == n / 3 ? 5.0 : 0.0);
    v.values[k] = 15.9 + 0.0001 * static_cast<double>(k % 13);
    if (k % 100003 == 17) i.values[k] = std::numeric_limits<double>::quiet_NaN();
  }
  t.channels = {std::move(i), std::move(v)};
  t.total_channel = "";
  t.phases = {{"load", 1.0, 2.0}};
  return t;
}

bool same_stats(const bs::SignalStats& a, const bs::SignalStats& b) {
  return a.summary.n == b.summary.n && same_bits(a.summary.mean, b.summary.mean) &&
         same_bits(a.summary.sd, b.summary.sd) && same_bits(a.summary.min, b.summary.min) &&
         same_bits(a.summary.max, b.summary.max) && same_bits(a.pct.p5, b.pct.p5) && same_bits(a.pct.p50, b.pct.p50) &&
         same_bits(a.pct.p95, b.pct.p95) && same_bits(a.pct.p99, b.pct.p99);
}

bool same_summary(const bs::TraceSummary& a, const bs::TraceSummary& b) {
  if (a.samples != b.samples || !same_bits(a.duration_s, b.duration_s) || a.channels.size() != b.channels.size())
    return false;
  for (std::size_t k = 0; k < a.channels.size(); ++k) {
    const auto& x = a.channels[k];
    const auto& y = b.channels[k];
    if (x.name != y.name || x.quantity != y.quantity || !same_stats(x.stats, y.stats) ||
        !same_bits(x.integral, y.integral) || !same_bits(x.overview.t, y.overview.t) ||
        !same_bits(x.overview.v, y.overview.v))
      return false;
  }
  return true;
}

bs::ImportBatch batch_of(bs::PowerTrace t) {
  return bs::test::batch_holding(&bs::ImportBatch::power_traces, {std::move(t)}, "long.csv", "power-csv");
}

}  // namespace

class TestPowerLazy : public QObject {
  Q_OBJECT
 private slots:
  void lazy_gives_the_same_numbers_as_eager() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("ws.bsw").toStdString();
    const std::size_t n = 3 * bs::store::kChunkSamples + 12345;
    const bs::PowerTrace original = make_trace(n);
    bs::Workspace(path).add_import(batch_of(original), "h1");

    bs::Workspace ws(path);
    const auto eager = ws.power_traces();
    auto lazy = ws.power_trace_summaries();
    QCOMPARE(eager.size(), std::size_t{1});
    QCOMPARE(lazy.size(), std::size_t{1});
    // Before loading: metadata, channel names and the cached summary, no samples.
    QVERIFY(!lazy[0].samples_loaded);
    QVERIFY(lazy[0].trace.time_s.empty());
    QCOMPARE(lazy[0].trace.channels.size(), std::size_t{2});
    QVERIFY(lazy[0].trace.channels[0].values.empty());
    QCOMPARE(lazy[0].summary.samples, n);
    QCOMPARE(lazy[0].trace.phases.size(), std::size_t{1});

    ws.load_power_samples(lazy[0]);
    QVERIFY(lazy[0].samples_loaded);
    for (const bs::PowerTrace* t : {static_cast<const bs::PowerTrace*>(&lazy[0].trace), &eager[0].trace}) {
      QVERIFY(same_bits(t->time_s, original.time_s));
      QCOMPARE(t->channels.size(), original.channels.size());
      for (std::size_t k = 0; k < original.channels.size(); ++k) {
        QCOMPARE(t->channels[k].name, original.channels[k].name);
        QVERIFY(same_bits(t->channels[k].values, original.channels[k].values));  // NaNs in place, bit for bit
      }
    }
    // The cached summary is what the analysis computes from the samples, whichever way they were loaded.
    const bs::TraceSummary from_samples = bs::summarize_trace(lazy[0].trace);
    QVERIFY(same_summary(lazy[0].summary, from_samples));
    QVERIFY(same_summary(eager[0].summary, bs::summarize_trace(original)));
    // And the statistics a view shows are those of the cached summary: n skips the missing samples.
    const bs::SignalStats direct = bs::signal_stats(original.channels[0].values);
    QVERIFY(same_stats(lazy[0].summary.channels[0].stats, direct));
    QVERIFY(direct.summary.n < n);
    QVERIFY(same_bits(lazy[0].summary.channels[0].integral,
                      bs::integrate_trapezoid(original.time_s, original.channels[0].values)));
    // The overview is a min/max decimation: the spike is in it, and it is short.
    const auto& ov = lazy[0].summary.channels[0].overview;
    QVERIFY(ov.v.size() <= 2 * bs::kOverviewColumns + 2);
    QCOMPARE(*std::max_element(ov.v.begin(), ov.v.end()), direct.summary.max);
    // Samples are chunks, not one BLOB per series.
    QCOMPARE(RawDb(path).scalar("SELECT COUNT(*) FROM power_chunks"), std::to_string(3 * 4));
    QCOMPARE(RawDb(path).scalar("SELECT length(time_s) FROM power_traces"), std::string("0"));
  }

  void loading_reports_progress_and_cancels() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("ws.bsw").toStdString();
    bs::Workspace(path).add_import(batch_of(make_trace(2 * bs::store::kChunkSamples + 7)), "h1");
    bs::Workspace ws(path);
    auto lazy = ws.power_trace_summaries();
    bs::CancelToken token;
    std::vector<double> seen;
    token.set_progress([&](double f, std::string_view) { seen.push_back(f); });
    ws.load_power_samples(lazy[0], &token);
    QVERIFY(seen.size() >= 3 * 3);  // three series of three chunks each
    QVERIFY(std::is_sorted(seen.begin(), seen.end()));
    QCOMPARE(seen.back(), 1.0);

    auto again = ws.power_trace_summaries();
    bs::CancelToken cancel;
    int calls = 0;
    cancel.set_progress([&](double, std::string_view) {
      if (++calls == 2) cancel.cancel();  // the user presses Cancel during the load
    });
    QVERIFY_THROWS_EXCEPTION(bs::Cancelled, ws.load_power_samples(again[0], &cancel));
    QVERIFY(!again[0].samples_loaded);
  }

  void import_is_cancelled_without_a_trace_left() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("ws.bsw").toStdString();
    bs::Workspace ws(path);
    bs::CancelToken cancel;
    cancel.set_progress([&](double f, std::string_view) {
      if (f > 0.5) cancel.cancel();  // halfway through storing the chunks
    });
    QVERIFY_THROWS_EXCEPTION(bs::Cancelled,
                             ws.add_import(batch_of(make_trace(4 * bs::store::kChunkSamples)), "h1", &cancel));
    QCOMPARE(ws.imports().size(), std::size_t{0});
    QCOMPARE(RawDb(path).scalar("SELECT COUNT(*) FROM power_chunks"), std::string("0"));
    QCOMPARE(RawDb(path).scalar("SELECT COUNT(*) FROM power_traces"), std::string("0"));
  }

  void schema5_trace_is_converted() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("v5.bsw").toStdString();
    const bs::PowerTrace original = make_trace(bs::store::kChunkSamples + 99);
    bs::Workspace(path).add_import(batch_of(original), "h1");
    {
      // What schema 5 left: the samples as one BLOB per series in the rows themselves, no chunks, no summary.
      sqlite3* db = nullptr;
      QCOMPARE(sqlite3_open(path.c_str(), &db), SQLITE_OK);
      const auto put = [&](const char* sql, const std::vector<double>& v) {
        sqlite3_stmt* st = nullptr;
        QCOMPARE(sqlite3_prepare_v2(db, sql, -1, &st, nullptr), SQLITE_OK);
        sqlite3_bind_blob64(st, 1, v.data(), v.size() * sizeof(double), SQLITE_TRANSIENT);
        QCOMPARE(sqlite3_step(st), SQLITE_DONE);
        sqlite3_finalize(st);
      };
      put("UPDATE power_traces SET time_s = ?", original.time_s);
      put("UPDATE power_channels SET vals = ? WHERE name = 'I'", original.channels[0].values);
      put("UPDATE power_channels SET vals = ? WHERE name = 'V'", original.channels[1].values);
      QCOMPARE(sqlite3_exec(db,
                            "DELETE FROM power_chunks; UPDATE power_traces SET samples = NULL, duration_s = NULL; "
                            "UPDATE power_channels SET summary = NULL, overview = NULL; PRAGMA user_version = 5;",
                            nullptr, nullptr, nullptr),
               SQLITE_OK);
      sqlite3_close(db);
    }
    for (int open = 0; open < 2; ++open) {  // the second open finds nothing left to convert
      bs::Workspace ws(path);
      QCOMPARE(ws.schema_version(), bs::Workspace::kSchemaVersion);
      auto lazy = ws.power_trace_summaries();
      QCOMPARE(lazy.size(), std::size_t{1});
      QCOMPARE(lazy[0].summary.samples, original.time_s.size());
      QVERIFY(same_summary(lazy[0].summary, bs::summarize_trace(original)));
      ws.load_power_samples(lazy[0]);
      QVERIFY(same_bits(lazy[0].trace.time_s, original.time_s));
      QVERIFY(same_bits(lazy[0].trace.channels[0].values, original.channels[0].values));
      QVERIFY(same_bits(lazy[0].trace.channels[1].values, original.channels[1].values));
      QCOMPARE(ws.integrity_check(), std::string("ok"));
    }
    QCOMPARE(RawDb(path).scalar("SELECT SUM(length(vals)) FROM power_channels"), std::string("0"));
  }

  void damaged_chunks_are_reported() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("ws.bsw").toStdString();
    bs::Workspace(path).add_import(batch_of(make_trace(2 * bs::store::kChunkSamples)), "h1");
    // Read the summary first, then lose a chunk: loading the samples notices before it allocates from the count.
    bs::Workspace ws(path);
    auto lazy = ws.power_trace_summaries();
    QVERIFY(RawDb(path, false).exec("DELETE FROM power_chunks WHERE series = 0 AND first > 0"));
    try {
      ws.load_power_samples(lazy[0]);
      QFAIL("a missing chunk was not noticed");
    } catch (const bs::WorkspaceError& e) {
      QCOMPARE(e.kind(), bs::WorkspaceError::Kind::Corrupt);
      QVERIFY2(std::string(e.what()).find("ws.bsw") != std::string::npos, e.what());
    }
    // Opened again, the trace is damaged: left out, named, and the workspace read-only (issue #37).
    bs::Workspace again(path);
    QVERIFY(again.power_trace_summaries().empty());
    QCOMPARE(again.damage().size(), std::size_t{1});
    QVERIFY2(again.damage()[0].item.find("power trace #1") == 0, again.damage()[0].item.c_str());
    QVERIFY2(again.damage()[0].reason.find("holds 262144 samples, its summary says 524288") != std::string::npos,
             again.damage()[0].reason.c_str());
    QVERIFY(again.read_only());
  }
};

QTEST_GUILESS_MAIN(TestPowerLazy)
#include "test_power_lazy.moc"
