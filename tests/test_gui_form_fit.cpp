// Every module's form at the screens an operator has (1280×720, 1366×768,
// 1920×1080, the window at the screen's free area) in English, Japanese and
// Chinese (issue 34, item 2): no label's text is cut or scrolled out of view
// while the focus goes from field to field, error texts wrap inside the
// form, and the form never scrolls sideways. At the same sizes (item 5) the
// step list shows the step, its tool, S, F and time, and a window left on a
// larger screen opens no larger than this one.
#include "model/job.h"
#include "modules/registry.h"
#include "support/speak.h"
#include "support/support.h"
#include "ui/job_document.h"
#include "ui/plan_runner.h"
#include "ui/station_window.h"
#include "ui/step_panel.h"
#include "ui/step_table.h"
#include "ui/unit_form.h"
#include "ui/unit_list_panel.h"

#include <QAbstractItemView>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QScreen>
#include <QScrollBar>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;

namespace {

// The visible form of the window.
UnitForm* shownForm(StationWindow& w)
{
    for (UnitForm* f : w.findChildren<UnitForm*>())
        if (f->isVisible()) return f;
    return nullptr;
}

// What is wrong with one label where the scroll area shows it; empty: nothing.
QString labelFault(const QLabel* l, const QWidget* viewport, bool mustBeInView)
{
    if (!l->isVisible()) return {};
    const QRect at(l->mapTo(viewport, QPoint(0, 0)), l->size());
    const QString what = QStringLiteral("'%1' (%2)").arg(l->text().left(40), l->objectName());
    if (at.left() < 0 || at.right() >= viewport->width())
        return QStringLiteral("%1 at x %2..%3 outside the view's 0..%4").arg(what).arg(at.left()).arg(at.right()).arg(viewport->width());
    if (mustBeInView && (at.top() < 0 || at.bottom() >= viewport->height()))
        return QStringLiteral("%1 at y %2..%3 outside the view's 0..%4").arg(what).arg(at.top()).arg(at.bottom()).arg(viewport->height());
    if (!l->pixmap().isNull()) {
        const int w = qRound(l->pixmap().deviceIndependentSize().width());
        return w <= l->contentsRect().width() ? QString() : QStringLiteral("%1: picture %2 wide in %3").arg(what).arg(w).arg(l->width());
    }
    if (l->text().isEmpty()) return {};
    if (l->wordWrap()) {
        const int needed = l->heightForWidth(l->width());
        return needed <= l->height() + 1 ? QString() : QStringLiteral("%1: needs %2 high, has %3").arg(what).arg(needed).arg(l->height());
    }
    // A label with a buddy draws "&N" as an underlined N: what is drawn is measured.
    QString drawn = l->text();
    if (l->buddy()) drawn.replace(QStringLiteral("&&"), QStringLiteral("\x01")).remove(QLatin1Char('&')).replace(QLatin1Char('\x01'), QLatin1Char('&'));
    const int needed = l->textFormat() == Qt::PlainText || !Qt::mightBeRichText(l->text())
                           ? l->fontMetrics().horizontalAdvance(drawn) + 2 * l->margin() + 2 * l->indent() * 0
                           : l->sizeHint().width();
    return needed <= l->contentsRect().width() ? QString()
                                               : QStringLiteral("%1: needs %2 wide, has %3").arg(what).arg(needed).arg(l->contentsRect().width());
}

// The fields of a form an operator tabs through (not a table's cells).
QList<QWidget*> fieldsOf(UnitForm* form)
{
    QList<QWidget*> out;
    for (QWidget* c : form->findChildren<QWidget*>()) {
        if (!qobject_cast<QLineEdit*>(c) && !qobject_cast<QComboBox*>(c)) continue;
        if (!c->isVisible() || qobject_cast<QComboBox*>(c->parentWidget())) continue;
        bool inTable = false;
        for (QWidget* p = c->parentWidget(); p && p != form; p = p->parentWidget())
            inTable = inTable || qobject_cast<QAbstractItemView*>(p);
        if (!inTable) out << c;
    }
    return out;
}

}  // namespace

class TestGuiFormFit : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    // Every label of the shown form after focusing each field in turn, then
    // with a long error under every field.
    // Every fault found, one a line (empty: none).
    static void checkForm(StationWindow& w, const QString& where, QStringList& faults)
    {
        UnitForm* form = shownForm(w);
        QVERIFY2(form, qPrintable(where));
        auto* scroll = w.findChild<QScrollArea*>("unit.scroll");
        QWidget* viewport = scroll->viewport();
        const auto check = [&](QWidget* focused, const QString& step) {
            for (int turn = 0; turn < 3; ++turn) QCoreApplication::processEvents();  // layouts, then the scroll area
            if (scroll->horizontalScrollBar()->maximum() != 0)
                faults << QStringLiteral("%1, %2: the form scrolls sideways by %3 (form %4 wide, view %5)")
                              .arg(where, step).arg(scroll->horizontalScrollBar()->maximum())
                              .arg(scroll->widget()->width()).arg(viewport->width());
            QLabel* own = nullptr;  // the focused field's label
            for (QLabel* l : form->findChildren<QLabel*>())
                if (focused && l->buddy() == focused) own = l;
            for (QLabel* l : form->findChildren<QLabel*>()) {
                const QString fault = labelFault(l, viewport, l == own);
                if (!fault.isEmpty()) faults << QStringLiteral("%1, %2: %3").arg(where, step, fault);
            }
        };
        const QList<QWidget*> fields = fieldsOf(form);
        QVERIFY2(!fields.isEmpty(), qPrintable(where));
        for (QWidget* f : fields) {
            f->setFocus(Qt::TabFocusReason);
            scroll->ensureWidgetVisible(f);  // what the scroll area does when Tab reaches it
            check(f, f->objectName());
        }
        // An error under every field: wrapped inside the form.
        const MachiningUnit& unit = w.document()->job().units[static_cast<std::size_t>(w.unitList()->currentUnit())];
        Diagnostics ds;
        for (const FieldSpec& f : form->fields())
            if (!f.diagFields.isEmpty())
                ds.push_back({Severity::Error, w.unitList()->currentUnit() + 1, unit.module.name(), f.diagFields.front().toStdString(),
                              "the value must be greater than the tool's radius and smaller than the stock's "
                              "width less both allowances, measured along the unit's own axis"});
        form->showDiagnostics(ds);
        for (QWidget* f : fields) {
            scroll->ensureWidgetVisible(f);
            check(f, f->objectName() + " with errors");
        }
        form->showDiagnostics({});
    }

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
    }
    void cleanup() { test::speak("en"); }

    void formsKeepTheirLabels_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QSize>("size");
        for (const char* language : {"en", "ja", "zh"})
            for (const QSize size : {QSize(1280, 672), QSize(1366, 720), QSize(1920, 1032)})
                QTest::newRow(qPrintable(QString("%1 %2").arg(language).arg(size.width()))) << QString(language) << size;
    }
    void formsKeepTheirLabels()
    {
        QFETCH(QString, language);
        QFETCH(QSize, size);
        test::speak(language.toUtf8().constData());
        int formsSeen = 0;
        QStringList faults;
        {
            // A milling job with a unit of every milling module.
            StationWindow w;
            w.resize(size);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            Job j = w.document()->job();
            j.units.clear();  // the job an earlier row's window left in the autosave comes back recovered
            for (const ModuleKind* kind : moduleKinds()) {
                if (kind->machineKind() != MachineKind::Mill) continue;
                if (j.figure.empty()) j.figure = kind->defaultFigure(j.stock);
                ModuleInput m = kind->makeDefault(toMillimetres(j).stock);
                const LengthUnit lu = j.lengthUnit;
                m.convertLengths([lu](double v) { return fromMm(v, lu); });
                j.units.push_back(MachiningUnit{"", m});
            }
            w.document()->edit(j, "every module", {}, 0);
            w.planRunner()->flush();
            for (int u = 0; u < static_cast<int>(j.units.size()); ++u) {
                w.unitList()->selectUnit(u);
                checkForm(w, QStringLiteral("%1 %2").arg(u + 1).arg(j.units[static_cast<std::size_t>(u)].module.name()), faults);
                if (QTest::currentTestFailed()) return;
                ++formsSeen;
            }
        }
        {
            StationWindow w(test::sourcePath("resources/samples/lathe-turned-shaft.taiwa"));
            w.resize(size);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            w.planRunner()->flush();
            w.unitList()->selectUnit(0);
            checkForm(w, "lathe 1", faults);
            if (QTest::currentTestFailed()) return;
            ++formsSeen;
        }
        QCOMPARE(formsSeen, static_cast<int>(moduleKinds().size()));
        faults.removeDuplicates();
        QVERIFY2(faults.isEmpty(), qPrintable(faults.join("\n").left(2000)));
    }

    // Item 5: at each screen the step list shows the selected step, its tool,
    // S, F and time whole (item 10: the time column at 1600 px, the window's
    // own first size, too), and the NC panel's heading (its label, the
    // dialect, the block count) is whole beside it.
    void stepListShowsTheStepAtEverySize_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QSize>("size");
        for (const char* language : {"en", "ja", "zh"})
            for (const QSize size : {QSize(1280, 672), QSize(1366, 720), QSize(1600, 900), QSize(1920, 1032)})
                QTest::newRow(qPrintable(QString("%1 %2").arg(language).arg(size.width()))) << QString(language) << size;
    }
    void stepListShowsTheStepAtEverySize()
    {
        QFETCH(QString, language);
        QFETCH(QSize, size);
        test::speak(language.toUtf8().constData());
        StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
        w.resize(size);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QCOMPARE(w.size(), size);
        w.planRunner()->flush();
        w.stepPanel()->selectStep(1);
        QCoreApplication::processEvents();
        StepTable* t = w.stepTable();
        QVERIFY(t->rowCount() > 1);
        for (const StepTable::Column c : {StepTable::No, StepTable::StepName, StepTable::ToolName, StepTable::Speed,
                                          StepTable::Feed, StepTable::Time}) {
            const QString head = t->horizontalHeaderItem(c)->text();
            QVERIFY2(!t->isColumnHidden(c), qPrintable(head + " hidden"));
            const int x = t->columnViewportPosition(c), width = t->columnWidth(c);
            QVERIFY2(x >= 0 && x + width <= t->viewport()->width(),
                     qPrintable(QString("%1 at %2..%3 of %4").arg(head).arg(x).arg(x + width).arg(t->viewport()->width())));
            const QString text = t->item(1, c)->text();
            QVERIFY2(t->fontMetrics().horizontalAdvance(text) <= width,
                     qPrintable(QString("%1: '%2' in %3 px").arg(head, text).arg(width)));
        }
        auto* tapes = w.findChild<QWidget*>("nc.tapes");
        QVERIFY(tapes);
        QStringList faults;
        for (const char* name : {"nc.label", "nc.blocks"}) {
            auto* l = tapes->findChild<QLabel*>(name);
            QVERIFY2(l && !l->text().isEmpty(), name);
            if (const QString fault = labelFault(l, tapes, true); !fault.isEmpty()) faults << fault;
        }
        auto* dialect = tapes->findChild<QComboBox*>("nc.dialect");
        QVERIFY(dialect);
        const QRect at(dialect->mapTo(tapes, QPoint(0, 0)), dialect->size());
        if (at.right() >= tapes->width() || dialect->width() < dialect->minimumSizeHint().width())
            faults << QStringLiteral("the dialect box at x %1..%2 of %3, %4 wide of %5").arg(at.left()).arg(at.right())
                          .arg(tapes->width()).arg(dialect->width()).arg(dialect->minimumSizeHint().width());
        QVERIFY2(faults.isEmpty(), qPrintable(faults.join("\n")));
    }

    // Left at 2600 x 1500 on a large screen, the window opens on this one
    // no larger than its free area.
    void restoredWindowFitsTheScreen()
    {
        {
            StationWindow w;
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            w.setGeometry(0, 0, 2600, 1500);
            QSettings().setValue("station/geometry", w.saveGeometry());
        }
        StationWindow again;
        const QRect free = again.screen()->availableGeometry();
        QVERIFY2(again.width() <= free.width() && again.height() <= free.height(),
                 qPrintable(QString("%1 x %2 on %3 x %4").arg(again.width()).arg(again.height()).arg(free.width()).arg(free.height())));
        again.show();
        QVERIFY(QTest::qWaitForWindowExposed(&again));
        QVERIFY(free.contains(again.geometry().topLeft()));
        QSettings().remove("station/geometry");
    }
};

QTEST_MAIN(TestGuiFormFit)
#include "test_gui_form_fit.moc"
