// The step table refilled for a new plan of the job (an edit) keeps its rows'
// items and changes only the cells whose contents changed, and ends as a
// table filled anew with that plan would be: every cell's text, tooltip,
// bold, flags and alignment, and every column's width. Checked on
// plate.taiwa with unit 1 deeper, with a cutting value set in the job, and
// with fewer and more steps than before.
#include "job/job_file.h"
#include "modules/m4/m4.h"
#include "pipeline/pipeline.h"
#include "support/support.h"
#include "tools/tool_library.h"
#include "ui/step_table.h"

#include <QApplication>
#include <QtTest>

#include <memory>

using namespace taiwa;
using taiwa::ui::StepTable;

namespace {

Job plate()
{
    const auto read = readJobFile(taiwa::test::sourcePath(QStringLiteral("resources/samples/plate.taiwa")).toStdString());
    return read.job ? *read.job : Job{};
}

std::shared_ptr<const Plan> planOf(const Job& job)
{
    return std::make_shared<const Plan>(planJob(job, TechnologyTable::builtIn(), defaultToolLibrary()));
}

QString describe(const QTableWidgetItem* it)
{
    if (!it) return "(none)";
    return QString("%1|%2|%3|%4|%5")
        .arg(it->text(), it->toolTip())
        .arg(it->font().bold())
        .arg(static_cast<int>(it->flags()))
        .arg(it->data(Qt::TextAlignmentRole).toInt());
}

// `table` shows what a new table shows of `plan`.
void sameAsNew(const StepTable& table, const std::shared_ptr<const Plan>& plan)
{
    StepTable fresh;
    fresh.setPlan(plan);
    QCOMPARE(table.rowCount(), fresh.rowCount());
    for (int r = 0; r < fresh.rowCount(); ++r)
        for (int c = 0; c < StepTable::ColumnCount; ++c)
            QCOMPARE(describe(table.item(r, c)), describe(fresh.item(r, c)));
    for (int c = 0; c < StepTable::ColumnCount; ++c) QCOMPARE(table.columnWidth(c), fresh.columnWidth(c));
}

}  // namespace

class TestGuiStepTable : public QObject {
    Q_OBJECT

private slots:
    void anEditChangesItsCellsOnly()
    {
        const Job before = plate();
        QVERIFY(!before.units.empty());
        Job after = before;
        after.units[0].module.as<M4Pocket>().depth += 0.5;
        StepTable table;
        table.setPlan(planOf(before));
        const int rows = table.rowCount();
        QVERIFY(rows > 5);
        std::vector<QTableWidgetItem*> items;
        std::vector<QString> texts;
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < StepTable::ColumnCount; ++c) {
                items.push_back(table.item(r, c));
                texts.push_back(table.item(r, c)->text());
            }
        const auto plan = planOf(after);
        QCOMPARE(static_cast<int>(plan->steps.size()), rows);
        table.setPlan(plan);
        int changed = 0;
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < StepTable::ColumnCount; ++c) {
                const std::size_t k = static_cast<std::size_t>(r) * StepTable::ColumnCount + c;
                QCOMPARE(table.item(r, c), items[k]);  // the same item
                if (table.item(r, c)->text() != texts[k]) {
                    ++changed;
                    QCOMPARE(plan->steps[static_cast<std::size_t>(r)].unit, 0);  // only unit 1's rows
                }
            }
        QVERIFY(changed > 0);
        sameAsNew(table, plan);
    }

    void cuttingValuesAndRowCountsAsNew()
    {
        Job job = plate();
        StepTable table;
        table.setPlan(planOf(job));
        // A speed typed for unit 1's roughing: bold, with its tooltip.
        job.units[0].cutting["roughing"].speed = 1234;
        const auto typed = planOf(job);
        table.setPlan(typed);
        sameAsNew(table, typed);
        int typedRows = 0;
        for (int r = 0; r < table.rowCount(); ++r) {
            const Step& s = typed->steps[static_cast<std::size_t>(r)];
            const bool set = s.unit == 0 && s.kind == StepKind::Roughing;
            typedRows += set ? 1 : 0;
            QCOMPARE(table.item(r, StepTable::Speed)->font().bold(), set);
            QCOMPARE(table.item(r, StepTable::Speed)->toolTip().isEmpty(), !set);
            if (set) QCOMPARE(table.item(r, StepTable::Speed)->text(), QString("1234"));
        }
        QVERIFY(typedRows > 0);
        // Fewer steps, then more again.
        Job fewer = job;
        fewer.units.resize(1);
        table.setPlan(planOf(fewer));
        sameAsNew(table, planOf(fewer));
        table.setPlan(typed);
        sameAsNew(table, typed);
        table.setPlan(nullptr);
        QCOMPARE(table.rowCount(), 0);
    }
};

QTEST_MAIN(TestGuiStepTable)
#include "test_gui_step_table.moc"
