// SPDX-License-Identifier: GPL-3.0-or-later
// Issue #51: an imported result's precision by the library's words-to-type rule (scripts/build-library.py,
// data_type_of), the measurements JSONs' own words; and a precision "not stated" never ranked against a stated one
// or against another framework.
#include <QTest>

#include "analysis/library/candidates.h"
#include "analysis/library/precision_words.h"

namespace {

bs::ResultSet loadgen(const std::string& platform, const std::string& precision, const std::string& framework,
                      double qps) {
  bs::ResultSet s;
  s.platform = platform;
  s.source_format = "mlperf-loadgen";
  s.backend = framework;
  s.provenance.origin = bs::DataOrigin::Measured;
  s.provenance.source_file = platform + ".txt";
  s.provenance.settings = {{"network", "ssd-mobilenet"}, {"scenario", "SingleStream"}};
  if (!precision.empty()) s.provenance.settings.emplace_back("precision", precision);
  bs::Measurement m;
  m.metric = "queries per second";
  m.unit = "1/s";
  m.values = {qps};
  s.measurements.push_back(m);
  return s;
}

}  // namespace

class TestLikeWithLike : public QObject {
  Q_OBJECT
 private slots:
  // The words of real measurements JSONs (the library's kept v0.5 / v1.1 / v3.0 files say these).
  void words_to_type() {
    const auto t = [](std::string_view w, std::string_view tr = {}) {
      const auto p = bs::precision_from_words(w, tr);
      return p ? p->type : std::string("not stated");
    };
    QCOMPARE(t("int8"), std::string("int8"));
    QCOMPARE(t("INT8."), std::string("int8"));
    QCOMPARE(t("We transform the original fp32 weight to int8 weight"), std::string("int8"));
    QCOMPARE(t("fp32 weights are quantized to int8"), std::string("int8"));
    QCOMPARE(t("No change.", "Quantized from int8 in ONNX to int8 in TensorRT"), std::string("int8"));
    QCOMPARE(bs::precision_from_words("No change.", "from int8 ... to int8")->field,
             std::string("weight_transformations"));
    QCOMPARE(t("mixed fp16 and int8"), std::string("not stated"));  // two types, no "to": not one precision
    QCOMPARE(t(""), std::string("not stated"));
    QCOMPARE(t("No change."), std::string("not stated"));
  }

  void frameworks_by_name() {
    QCOMPARE(bs::framework_of("TensorRT 8.5.2, CUDA 11.4"), std::string("TensorRT"));
    QCOMPARE(bs::framework_of("SSD MobileNet (TensorFlow, MS COCO)"), std::string("TensorFlow"));
    QCOMPARE(bs::framework_of("TensorFlow Lite v2.11.0"), std::string("TFLite"));
    QCOMPARE(bs::framework_of("MLPerf LoadGen"), std::string());
  }

  // A TensorRT run of unknown precision is not ranked with a TensorFlow one of unknown precision, nor with an INT8
  // one; one with no framework either is alone; two of one framework share a class.
  void not_stated_is_ranked_only_with_its_framework() {
    const std::vector<bs::ResultSet> sets{
        loadgen("trt-a", "", "TensorRT 8.5", 900), loadgen("trt-b", "", "TensorRT 8.6", 800),
        loadgen("tf", "", "TensorFlow 2.4", 50), loadgen("int8", "int8", "TensorRT 8.5", 1000),
        loadgen("bare", "", "MLPerf LoadGen", 2000)};
    bs::CandidateInputs in;
    in.result_sets = sets;
    const auto classes = bs::rank_candidates(in, {});
    QCOMPARE(classes.size(), std::size_t{4});
    const auto find = [&](const std::string& title) -> const bs::CandidateClass* {
      for (const auto& c : classes)
        if (c.title() == title) return &c;
      return nullptr;
    };
    const auto* trt = find("ssd-mobilenet, SingleStream, not stated (TensorRT)");
    QVERIFY(trt);
    QCOMPARE(trt->rows.size(), std::size_t{2});
    QVERIFY(trt->rows[0].recommended);
    QCOMPARE(trt->rows[0].platform, std::string("trt-a"));
    QCOMPARE(find("ssd-mobilenet, SingleStream, not stated (TensorFlow)")->rows.size(), std::size_t{1});
    QCOMPARE(find("ssd-mobilenet, SingleStream, int8")->rows.size(), std::size_t{1});
    QCOMPARE(find("ssd-mobilenet, SingleStream, not stated (framework not stated)")->rows.at(0).platform,
             std::string("bare"));
  }
};

QTEST_APPLESS_MAIN(TestLikeWithLike)
#include "test_like_with_like.moc"
