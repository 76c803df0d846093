// SPDX-License-Identifier: GPL-3.0-or-later
// The workspace tree: platform -> device -> backend -> run, tristate checkboxes and the visible-run signal.
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QTest>

#include "workspace/workspace_tree.h"

namespace {

bs::StoredRun stored(std::int64_t id, const char* platform, const char* device, const char* backend, int dims) {
  bs::StoredRun s;
  s.id = id;
  s.color_index = static_cast<int>(id);
  s.run.platform = platform;
  s.run.device = device;
  s.run.backend = backend;
  s.run.dims = dims;
  s.run.samples = {{256, {0.01}}};
  s.run.provenance.origin = bs::DataOrigin::Reconstructed;
  s.run.provenance.host = "nuc-lab";
  s.run.provenance.source_file = "/data/gpu-nuc.json";
  return s;
}

}  // namespace

class TestWorkspaceTree : public QObject {
  Q_OBJECT
 private slots:
  void groups_runs_and_toggles_visibility() {
    bs::ui::WorkspaceTree tree;
    tree.set_runs({stored(1, "NUC", "NUC GPU", "OpenCL", 1), stored(2, "NUC", "NUC GPU", "OpenCL", 4),
                   stored(3, "NUC", "NUC CPU", "CPU SIMD", 4), stored(4, "Jetson TX2", "Jetson GPU", "CUDA", 4)});
    auto* model = qobject_cast<QStandardItemModel*>(tree.model());
    QVERIFY(model);
    QCOMPARE(model->rowCount(), 2);  // two platforms
    QStandardItem* nuc = model->item(0);
    QCOMPARE(nuc->text(), QString("NUC"));
    QCOMPARE(nuc->rowCount(), 2);  // NUC GPU, NUC CPU
    QStandardItem* gpu = nuc->child(0);
    QCOMPARE(gpu->child(0)->text(), QString("OpenCL"));
    QCOMPARE(gpu->child(0)->rowCount(), 2);  // D=1 and D=4
    QVERIFY(gpu->child(0)->child(0)->toolTip().contains("reconstructed"));
    QVERIFY(gpu->child(0)->child(0)->toolTip().contains("/data/gpu-nuc.json"));
    QVERIFY(gpu->child(0)->child(0)->toolTip().contains("nuc-lab"));
    QCOMPARE(tree.visible_runs(), (QSet<qint64>{1, 2, 3, 4}));

    // Unticking one run: the parents become partially checked and the signal carries the visible set.
    QSignalSpy spy(&tree, &bs::ui::WorkspaceTree::visibility_changed);
    gpu->child(0)->child(0)->setCheckState(Qt::Unchecked);
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.last().at(0).value<QSet<qint64>>(), (QSet<qint64>{2, 3, 4}));
    QCOMPARE(gpu->checkState(), Qt::PartiallyChecked);
    QCOMPARE(nuc->checkState(), Qt::PartiallyChecked);

    // Unticking a platform hides everything below it.
    nuc->setCheckState(Qt::Unchecked);
    QCOMPARE(tree.visible_runs(), (QSet<qint64>{4}));
    QCOMPARE(spy.last().at(0).value<QSet<qint64>>(), (QSet<qint64>{4}));

    // A reload (after an import) keeps what the user hid and shows new runs.
    tree.set_runs({stored(1, "NUC", "NUC GPU", "OpenCL", 1), stored(2, "NUC", "NUC GPU", "OpenCL", 4),
                   stored(3, "NUC", "NUC CPU", "CPU SIMD", 4), stored(4, "Jetson TX2", "Jetson GPU", "CUDA", 4),
                   stored(5, "Jetson TX2", "Jetson CPU", "CPU SIMD", 4)});
    QCOMPARE(tree.visible_runs(), (QSet<qint64>{4, 5}));
    QCOMPARE(tree.run_count(), 5);
  }
};

QTEST_MAIN(TestWorkspaceTree)
#include "test_workspace_tree.moc"
