// SPDX-License-Identifier: GPL-3.0-or-later
// The preprocessing stages on the roofline: op and byte counts of a tiny geometry counted by hand, intensity and
// placement arithmetic, ceiling matching, and the paper's NUC and Jetson runs placed from a sample workspace.
#include <cmath>
#include <filesystem>

#include <QTemporaryDir>
#include <QTest>

#include "../../../support/run_on.h"
#include "analysis/roofline/stage_roofline.h"
#include "store/workspace.h"
#include "workspace/registry.h"

namespace {

bool close(double a, double b, double rel = 1e-12) {
  return std::fabs(a - b) <= rel * std::max(std::fabs(a), std::fabs(b));
}

bs::PipelineRun run_of(const std::string& platform, const std::string& device, const std::string& backend,
                       const std::string& demosaic, int w, int h, double mean_s, double sd_s) {
  auto r = bs::test::run_on<bs::PipelineRun>(platform, device, backend);
  r.demosaic = demosaic;
  r.frame_width = w;
  r.frame_height = h;
  r.stages.push_back({bs::pipeline_stage::kPreprocess, 10, mean_s, sd_s, {}, {}, {}, {}});
  r.provenance.source_file = platform + ".json";
  return r;
}

}  // namespace

class TestStageRoofline : public QObject {
  Q_OBJECT
 private slots:
  void per_site_counts_by_hand() {
    // Bilinear: a green site averages 2 + 2 samples ((w + e + 1) >> 1: 2 adds + shift, twice) = 6; a red or blue
    // site 4 + 4 ((n + s + w + e + 2) >> 2: 4 adds + shift, twice) = 10. Cell (G, G, R, B): (6 + 6 + 10 + 10) / 4.
    QCOMPARE(bs::kernel_cost(bs::StageKernel::DemosaicBilinear).ops_per_pixel, 8.0);
    // MHC: (2 x 27 + 2 x 23) / 4.
    QCOMPARE(bs::kernel_cost(bs::StageKernel::DemosaicMhc).ops_per_pixel, 25.0);
    // remap: 3 channels x (4 mul + 3 add + 1 add + 1 shift).
    QCOMPARE(bs::kernel_cost(bs::StageKernel::Reprojection).ops_per_pixel, 27.0);
    // fused: 2 weights + (5 + 5 + 7 + 7) taps + 3 x 11 blend.
    QCOMPARE(bs::kernel_cost(bs::StageKernel::Fused).ops_per_pixel, 59.0);
    // Bytes per pixel that do not depend on the geometry: 1 in + 3 out; 6 LUT + 3 out; 8 table + 3 out.
    QCOMPARE(bs::kernel_cost(bs::StageKernel::DemosaicBilinear).bytes_per_pixel, 4.0);
    QCOMPARE(bs::kernel_cost(bs::StageKernel::Reprojection).bytes_per_pixel, 9.0);
    QCOMPARE(bs::kernel_cost(bs::StageKernel::Fused).bytes_per_pixel, 11.0);
  }

  void tiny_geometry_by_hand() {
    // A 4x4 mosaic reprojected into a 2x2 view.
    const bs::FrameGeometry g{4, 4, 2, 2};
    const std::vector<bs::StageKernel> separate{bs::StageKernel::DemosaicBilinear, bs::StageKernel::Reprojection};
    const bs::StageCost s = bs::stage_cost(separate, g);
    // Ops: 16 mosaic pixels x 8 + 4 output pixels x 27 = 128 + 108 = 236.
    QCOMPARE(s.ops, 236.0);
    // Bytes: demosaic 16 x (1 + 3) = 64; reprojection 4 x (6 LUT + 3 out) = 36 plus the 16-pixel RGB source read
    // once, 48: 148 in all.
    QCOMPARE(s.bytes, 148.0);
    QCOMPARE(s.intensity(), 236.0 / 148.0);
    QCOMPARE(s.ops_per_output_pixel, 59.0);
    QCOMPARE(s.bytes_per_output_pixel, 37.0);
    QCOMPARE(QString::fromStdString(s.label),
             QString("demosaic (bilinear) + reprojection (bilinear, fixed-point LUT)"));

    // Fused: 4 x 59 = 236 ops (the same work, no RGB frame in between); bytes 4 x (8 + 3) + 16 x 1 = 60.
    const std::vector<bs::StageKernel> fused{bs::StageKernel::Fused};
    const bs::StageCost f = bs::stage_cost(fused, g);
    QCOMPARE(f.ops, 236.0);
    QCOMPARE(f.bytes, 60.0);
    QVERIFY(f.intensity() > s.intensity());

    // MHC + reprojection: 16 x 25 + 108 = 508 ops over the same 148 bytes.
    const std::vector<bs::StageKernel> mhc{bs::StageKernel::DemosaicMhc, bs::StageKernel::Reprojection};
    QCOMPARE(bs::stage_cost(mhc, g).ops, 508.0);
    QCOMPARE(bs::stage_cost(mhc, g).bytes, 148.0);

    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::stage_cost(separate, bs::FrameGeometry{0, 4, 2, 2}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::stage_cost(std::vector<bs::StageKernel>{}, g));
  }

  void kernels_from_the_run() {
    QCOMPARE(bs::preprocessing_kernels("fused")->size(), std::size_t{1});
    QVERIFY(bs::preprocessing_kernels("")->front() == bs::StageKernel::DemosaicBilinear);  // the paper's
    QVERIFY(bs::preprocessing_kernels("mhc")->front() == bs::StageKernel::DemosaicMhc);
    QVERIFY(!bs::preprocessing_kernels("opencv-vng"));
  }

  void placement_arithmetic() {
    // A 1000x1000 frame in 10 ms (SD 2 ms) on a device of 100 GOP/s and 10 GB/s.
    const bs::RooflineCeiling c{"robot",      "CPU", 100e9, "theoretical", 10e9, "triad", bs::DeviceKind::Cpu,
                                std::nullopt, "",    {}};
    const std::vector<bs::RooflineCeiling> cs{c};
    const std::vector<bs::PipelineRun> runs{
        run_of("robot", "CPU (4 threads)", "cpu", "bilinear", 1000, 1000, 0.010, 0.002)};
    const bs::StagePlacements p = bs::place_preprocessing(cs, runs);
    QCOMPARE(p.placed.size(), std::size_t{1});
    const bs::StagePlacement& s = p.placed.front();
    QCOMPARE(QString::fromStdString(s.device), QString("CPU"));  // by kind: "cpu" backend -> the CPU ceiling
    // 1e6 px x (8 + 27) = 35e6 ops; 1e6 x (4 + 9 + 3) = 16e6 bytes; I = 35/16; 35e6 / 0.01 s = 3.5e9 op/s.
    QCOMPARE(s.cost.ops, 35e6);
    QCOMPARE(s.cost.bytes, 16e6);
    QCOMPARE(s.point.intensity, 35.0 / 16.0);
    QVERIFY(close(s.point.flops, 3.5e9));
    // The roof at I = 2.1875 is memory-bound: 21.875 GB/s-worth of ops; 3.5 / 21.875 of it.
    QVERIFY(close(s.point.attainable, 21.875e9));
    QVERIFY(close(s.point.fraction, 3.5 / 21.875));
    QVERIFY(s.point.memory_bound);
    QVERIFY(close(*s.ops_per_s_low, 35e6 / 0.012));
    QVERIFY(close(*s.ops_per_s_high, 35e6 / 0.008));
    QVERIFY(s.geometry_assumed);
  }

  void ceiling_matching() {
    const std::vector<bs::RooflineCeiling> cs{
        {"box", "GPU", 1e12, "", std::nullopt, "", bs::DeviceKind::Gpu, std::nullopt, "", {}},
        {"box", "GPU X", 2e12, "", std::nullopt, "", bs::DeviceKind::Gpu, std::nullopt, "", {}},
        {"box", "CPU", 1e11, "", std::nullopt, "", bs::DeviceKind::Cpu, std::nullopt, "", {}}};
    const std::vector<bs::PipelineRun> runs{
        run_of("box", "GPU X (OpenCL) preprocessing, CPU detection", "opencl", "", 8, 8, 1e-3, 0),  // longest name
        run_of("box", "something else", "opencl", "", 8, 8, 1e-3, 0),  // two GPUs: ambiguous, skipped
        run_of("box", "CPU", "cpu", "opencv-ea", 8, 8, 1e-3, 0),       // no op model
        run_of("box", "CPU", "cpu", "bilinear", 0, 0, 1e-3, 0),        // no frame size
        run_of("other", "CPU", "cpu", "bilinear", 8, 8, 1e-3, 0)};     // no ceiling at all
    const bs::StagePlacements p = bs::place_preprocessing(cs, runs);
    QCOMPARE(p.placed.size(), std::size_t{1});
    QCOMPARE(QString::fromStdString(p.placed.front().device), QString("GPU X"));
    QCOMPARE(p.skipped.size(), std::size_t{4});
    QVERIFY(QString::fromStdString(p.skipped[1]).contains("opencv-ea"));
    QVERIFY(QString::fromStdString(p.skipped[2]).contains("frame size"));
  }

  void paper_workspace_places_nuc_and_jetson() {
    QTemporaryDir dir;
    bs::Workspace ws(dir.filePath("paper.bsw").toStdString());
    int n = 0;
    for (const auto& e : std::filesystem::directory_iterator(BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018")) {
      if (!e.is_regular_file() || e.path().extension() != ".json") continue;
      ws.add_import(bs::import_file(e.path().string(), bs::CancelToken{}), e.path().filename().string());
      ++n;
    }
    QVERIFY(n >= 6);
    std::vector<bs::FlopsRun> runs;
    for (const auto& r : ws.runs()) runs.push_back(r.run);
    std::vector<bs::ResultSet> sets;
    for (const auto& s : ws.result_sets()) sets.push_back(s.set);
    std::vector<bs::PipelineRun> pipelines;
    for (const auto& p : ws.pipeline_runs()) pipelines.push_back(p.run);
    const auto ceilings = bs::roofline_ceilings(runs, sets);
    const bs::StagePlacements p = bs::place_preprocessing(ceilings, pipelines);
    QCOMPARE(p.placed.size(), std::size_t{2});
    QVERIFY(p.skipped.empty());
    // 1280 x 1024 in and out, bilinear demosaic then reprojection: 35 ops and 16 bytes per pixel.
    const double ops = 35.0 * 1280 * 1024;
    for (const bs::StagePlacement& s : p.placed) {
      QCOMPARE(s.cost.ops, ops);
      QCOMPARE(s.point.intensity, 35.0 / 16.0);
      if (s.platform == "NUC") {
        QCOMPARE(QString::fromStdString(s.device), QString("NUC GPU (Iris Plus 650)"));
        QVERIFY(close(s.point.flops, ops / 0.00621));  // 6.21 ms: 7.39 Gop/s
        QVERIFY(close(*s.ops_per_s_high, ops / (0.00621 - 0.00099)));
      } else {
        QCOMPARE(QString::fromStdString(s.platform), QString("Jetson TX2"));
        QCOMPARE(QString::fromStdString(s.device), QString("Jetson GPU (Pascal, 256 cores)"));
        QVERIFY(close(s.point.flops, ops / 0.00648));
        QVERIFY(close(*s.ops_per_s_high, ops / (0.00648 - 0.00243)));
      }
      QCOMPARE(s.origin, bs::DataOrigin::Reconstructed);
      QVERIFY(s.point.fraction > 0 && s.point.fraction < 1);
    }
  }
};

QTEST_APPLESS_MAIN(TestStageRoofline)
#include "test_stage_roofline.moc"
