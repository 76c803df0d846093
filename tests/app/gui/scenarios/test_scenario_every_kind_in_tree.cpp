// SPDX-License-Identifier: GPL-3.0-or-later
// Scenario (issue #52): every kind of record a workspace holds has its rows in the workspace tree, and a person can
// take one out there and put it back. Before #52 the tree had no rows for inference runs (`bench dnn`) or sustained
// runs (`sustain`): they showed in the Platforms and Sustained tabs, but nothing in the window could remove them,
// and the undo text of a removal did not count them.
//  - runs_leave_and_come_back_from_the_tree: the paper's workspace, plus one inference run and one sustained run
//    stored the way `benchscope-cli bench dnn` and `benchscope-cli sustain` store them (their batch builders and
//    bring_home). The tree shows "Inference runs (1)" and "Sustained runs (1)"; a click on the sustained run's row
//    and Delete take its import out (the Sustained tab empties; the status bar names "1 sustained run"); Ctrl+Z
//    brings it back. The same for the inference run and the Platforms tab's inference table.
#include <QStandardItemModel>
#include <QTableWidget>
#include <QTest>
#include <QTreeView>

#include "../../../support/sample_records.h"
#include "../../../support/scenario_window.h"
#include "platform/inference_table.h"
#include "store/home_batch.h"
#include "sustain/sustain_import.h"
#include "sustain/sustain_view.h"
#include "vision/dnn_home.h"
#include "workspace/workspace_tree.h"

namespace {

using Kind = bs::ui::TreeItemRef::Kind;

// The tree's section of `kind` (a top-level row titled "Sustained runs (1)" ...), or null when it has none.
QStandardItem* section_of(bs::ui::WorkspaceTree& tree, Kind kind) {
  auto* model = qobject_cast<QStandardItemModel*>(tree.model());
  for (int r = 0; r < model->rowCount(); ++r) {
    QStandardItem* top = model->item(r);
    if (top->rowCount() > 0 && tree.ref_at(top->child(0)->index()).kind == kind) return top;
  }
  return nullptr;
}

// A click on the first row of `kind`'s section (opened first, as a person opens it) and Delete, as a person does.
bool delete_first_row(bs::ui::WorkspaceTree& tree, Kind kind) {
  QStandardItem* section = section_of(tree, kind);
  if (!section) return false;
  tree.expand(section->index());
  const QModelIndex row = section->child(0)->index();
  tree.scrollTo(row);
  QTest::qWait(20);
  QTest::mouseClick(tree.viewport(), Qt::LeftButton, {}, tree.visualRect(row).center());
  if (tree.current_ref().kind != kind) return false;
  QTest::keyClick(&tree, Qt::Key_Delete);
  return true;
}

}  // namespace

class TestScenarioEveryKindInTree : public QObject {
  Q_OBJECT
 private slots:
  void runs_leave_and_come_back_from_the_tree() {
    QTemporaryDir dir;
    const QString ws = bs::test::paper_workspace(dir);
    QVERIFY(!ws.isEmpty());
    bs::bring_home(ws.toStdString(), bs::sustain::sustain_import(bs::test::sample_sustained_run("NUC", 50, 49),
                                                                 std::nullopt, "benchscope-cli sustain"));
    bs::bring_home(ws.toStdString(), bs::dnn_home({bs::test::sample_inference_run("NUC", "NUC CPU")}, std::nullopt,
                                                  "benchscope-cli bench dnn"));

    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(ws));
    QVERIFY(bs::test::show_at(w, 1280, 800));
    bs::ui::WorkspaceTree* tree = w.tree();
    QStandardItem* sustained = section_of(*tree, Kind::SustainedRun);
    QStandardItem* inference = section_of(*tree, Kind::InferenceRun);
    QVERIFY2(sustained && inference, "the tree has no section for sustained or inference runs");
    QCOMPARE(sustained->text(), QStringLiteral("Sustained runs (1)"));
    QCOMPARE(inference->text(), QStringLiteral("Inference runs (1)"));
    tree->expand(sustained->index());
    tree->expand(inference->index());
    bs::test::screenshot(&w, "workspace-tree-every-kind-1280x800");
    w.resize(1600, 1000);
    QTest::qWait(50);
    bs::test::screenshot(&w, "workspace-tree-every-kind-1600x1000");

    // The sustained run: out with Delete, the Sustained tab empties; back with Ctrl+Z.
    QVERIFY(bs::test::open_tab(w, "Sustained"));
    QCOMPARE(w.sustain_view()->chooser()->count(), 1);
    QVERIFY(delete_first_row(*tree, Kind::SustainedRun));
    QVERIFY(bs::test::wait_until([&] { return tree->item_count(Kind::SustainedRun) == 0; }));
    QCOMPARE(w.sustain_view()->chooser()->count(), 0);
    QVERIFY2(bs::test::status(w).contains("(1 sustained run)"), qPrintable(bs::test::status(w)));
    QCOMPARE(tree->item_count(Kind::InferenceRun), 1);  // the other import stays
    bs::test::press(w, Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(bs::test::wait_until([&] { return tree->item_count(Kind::SustainedRun) == 1; }));
    QCOMPARE(w.sustain_view()->chooser()->count(), 1);

    // The inference run: the same, seen in the Platforms tab's inference table.
    QVERIFY(bs::test::open_tab(w, "Platforms"));
    bs::ui::InferenceTable* table = w.platform_view()->inference_table();
    QCOMPARE(table->runs().size(), std::size_t{1});
    QVERIFY(delete_first_row(*tree, Kind::InferenceRun));
    QVERIFY(bs::test::wait_until([&] { return tree->item_count(Kind::InferenceRun) == 0; }));
    QCOMPARE(table->runs().size(), std::size_t{0});
    QVERIFY2(bs::test::status(w).contains("(1 inference run)"), qPrintable(bs::test::status(w)));
    bs::test::press(w, Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(bs::test::wait_until([&] { return tree->item_count(Kind::InferenceRun) == 1; }));
    QCOMPARE(table->runs().size(), std::size_t{1});
    QCOMPARE(tree->item_count(Kind::SustainedRun), 1);
  }
};

BENCHSCOPE_SCENARIO_MAIN(TestScenarioEveryKindInTree)
#include "test_scenario_every_kind_in_tree.moc"
