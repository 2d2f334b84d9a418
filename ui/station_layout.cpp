// The station window's panels and menus (StationWindow::buildLeft,
// buildCentre, buildRight, buildMenus): what is where, and the menus'
// actions. The constructor (station_window.cpp) calls them, then wire()
// (station_wiring.cpp).
#include "ui/station_window.h"

#include "modules/registry.h"
#include "sim/stock_simulation.h"
#include "ui/core_texts.h"
#include "ui/figure_panel.h"
#include "ui/file_actions.h"
#include "ui/form_stack.h"
#include "ui/job_document.h"
#include "ui/job_properties.h"
#include "ui/language.h"
#include "ui/module_palette.h"
#include "ui/nc_view.h"
#include "ui/plan_runner.h"
#include "ui/preview_widget.h"
#include "ui/section_bar.h"
#include "ui/step_panel.h"
#include "ui/store_actions.h"
#include "ui/two_path_chart.h"
#include "ui/two_path_views.h"
#include "ui/unit_form.h"
#include "ui/unit_list_panel.h"
#include "ui/verification_panel.h"

#include <QActionGroup>
#include <QCoreApplication>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QOpenGLContext>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QSplitter>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <iterator>

namespace taiwa::ui {

QWidget* StationWindow::buildLeft()
{
    auto* left = new QWidget;
    auto* box = new QVBoxLayout(left);
    auto* paletteGroup = new QGroupBox;
    paletteGroup->setObjectName("group.modules");
    (new QVBoxLayout(paletteGroup))->addWidget(palette_);
    auto* unitsGroup = new QGroupBox;
    unitsGroup->setObjectName("group.units");
    (new QVBoxLayout(unitsGroup))->addWidget(units_);
    auto* jobGroup = new QGroupBox;
    jobGroup->setObjectName("group.job");
    auto* jobBox = new QVBoxLayout(jobGroup);
    jobBox->addWidget(jobProps_);
    auto* dialogs = new QHBoxLayout;
    auto* technology = new QPushButton;
    technology->setObjectName("job.technology");
    auto* tools = new QPushButton;
    tools->setObjectName("job.tools");
    dialogs->addWidget(technology);
    dialogs->addWidget(tools);
    jobBox->addLayout(dialogs);
    connect(technology, &QPushButton::clicked, this, &StationWindow::editTechnology);
    connect(tools, &QPushButton::clicked, this, &StationWindow::showToolLibrary);
    box->addWidget(paletteGroup);
    box->addWidget(unitsGroup, 1);
    box->addWidget(jobGroup);
    // On a low screen (720 pixels) the column scrolls rather than push the
    // window off the screen.
    auto* scroll = new QScrollArea;
    scroll->setObjectName("station.left");
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(left);
    scroll->setMinimumWidth(left->minimumSizeHint().width() + 16);  // and its scroll bar
    return scroll;
}

QWidget* StationWindow::buildCentre()
{
    auto* empty = new QLabel;
    empty->setObjectName("unit.none");
    empty->setAlignment(Qt::AlignCenter);
    empty->setWordWrap(true);
    forms_->addWidget(empty);
    for (const ModuleKind* kind : moduleKinds()) forms_->addWidget(unitForms_.at(kind->name()));
    unitMessages_->setObjectName("unit.messages");
    unitMessages_->setStyleSheet("color: #a00000;");
    unitMessages_->setWordWrap(true);
    auto* formGroup = new QGroupBox;
    formGroup->setObjectName("group.unit");
    auto* scroll = new QScrollArea;
    scroll->setObjectName("unit.scroll");
    scroll->setMinimumWidth(300);  // a form's labels and fields stay readable when the window is narrow
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(forms_);
    auto* box = new QVBoxLayout(formGroup);
    box->addWidget(scroll, 1);
    box->addWidget(unitMessages_);
    return formGroup;
}

QWidget* StationWindow::buildRight()
{
    auto* right = new QSplitter(Qt::Vertical);
    // Over the views while they show the last valid plan and the job has errors.
    stale_ = new QLabel;
    stale_->setObjectName("output.stale");
    stale_->setWordWrap(true);
    stale_->setStyleSheet("background: #fff3c4; color: #5a4500; padding: 4px; border: 1px solid #e0c060;");
    stale_->hide();
    // The 3-D view, and beside it (a milling job's) figure elements.
    views_ = new QTabWidget;
    views_->setObjectName("station.views");
    views_->setDocumentMode(true);
    if (QOpenGLContext().create()) {
        preview_ = new PreviewWidget;
        preview_->setObjectName("preview");
        preview_->setScaleNoteText([](int mm) { return axesNote(mm).toStdString(); }, axesNoteFont().toStdString());
        preview_->setMinimumSize(320, 240);
        section_ = new SectionBar;
        section_->setObjectName("section");
        auto* view = new QWidget;
        auto* box = new QVBoxLayout(view);
        box->setContentsMargins(0, 0, 0, 0);
        box->setSpacing(2);
        box->addWidget(preview_, 1);
        // The view's bar: the section, the paths switch, the zoom to the step.
        auto* bar = new QHBoxLayout;
        bar->addWidget(section_, 1);
        bar->addWidget(steps_->viewBar());
        steps_->viewBar()->show();
        box->addLayout(bar);
        views_->addTab(view, QString());
    } else {  // e.g. a remote display or the offscreen platform: everything else still works
        auto* noGl = new QLabel;
        noGl->setObjectName("preview.unavailable");
        noGl->setAlignment(Qt::AlignCenter);
        noGl->setFrameShape(QFrame::StyledPanel);
        views_->addTab(noGl, QString());
    }
    figure_ = new FigurePanel(doc_);
    figure_->setObjectName("figure");
    views_->addTab(figure_, QString());
    // A two-path job's timeline chart under the views (hidden for any other).
    auto* viewsAndChart = new QWidget;
    auto* viewsBox = new QVBoxLayout(viewsAndChart);
    viewsBox->setContentsMargins(0, 0, 0, 0);
    viewsBox->setSpacing(2);
    viewsBox->addWidget(views_, 1);
    viewsBox->addWidget(twoPath_->chart());
    twoPath_->chart()->hide();
    right->addWidget(viewsAndChart);
    // The step list and, for a two-path job, its steps by path; the tape
    // and path 2's (the tab bars shown for a two-path job only).
    stepTabs_ = new QTabWidget;
    stepTabs_->setObjectName("steps.tabs");
    stepTabs_->setDocumentMode(true);
    stepTabs_->addTab(steps_, QString());
    stepTabs_->addTab(twoPath_->steps(), QString());
    tapes_ = new QTabWidget;
    tapes_->setObjectName("nc.tapes");
    tapes_->setDocumentMode(true);
    tapes_->addTab(nc_, QString());
    tapes_->addTab(twoPath_->tape(), QString());
    for (QTabWidget* tabs : {stepTabs_, tapes_}) {
        tabs->setTabVisible(1, false);
        tabs->tabBar()->hide();
    }
    auto* lower = new QSplitter(Qt::Horizontal);
    lower->addWidget(stepTabs_);
    // The tape over the verification's findings.
    auto* tape = new QSplitter(Qt::Vertical);
    tape->addWidget(tapes_);
    tape->addWidget(verify_);
    tape->setStretchFactor(0, 3);
    tape->setStretchFactor(1, 1);
    lower->addWidget(tape);
    // The step list's columns (No., unit, step, tool, S, F, depths, time)
    // fit without scrolling sideways on a 1600-pixel screen; narrower, the
    // list hides its depths and unit columns, and the tape keeps 200 pixels
    // at 1280.
    lower->setStretchFactor(0, 12);
    lower->setStretchFactor(1, 8);
    right->addWidget(lower);
    right->setSizes({500, 440});
    auto* box = new QWidget;
    auto* layout = new QVBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(stale_);
    layout->addWidget(right, 1);
    return box;
}

void StationWindow::nameParts()
{
    const auto title = [this](const char* name, const QString& text) {
        if (auto* g = findChild<QGroupBox*>(QString::fromLatin1(name))) g->setTitle(text);
    };
    title("group.modules", tr("Modules"));
    title("group.units", tr("Machining units, in order"));
    title("group.job", tr("Job"));
    title("group.unit", tr("Unit"));
    findChild<QPushButton*>("job.technology")->setText(tr("Technology data…"));
    findChild<QPushButton*>("job.tools")->setText(tr("Tool library…"));
    findChild<QLabel*>("unit.none")->setText(tr("Pick a module on the left to add a machining unit."));
    if (auto* noGl = findChild<QLabel*>("preview.unavailable")) noGl->setText(tr("No 3-D preview: this display has no OpenGL."));
    views_->setTabText(0, tr("3-D view"));
    views_->setTabText(views_->indexOf(figure_), tr("Figure"));
    stepTabs_->setTabText(0, tr("Steps"));
    stepTabs_->setTabText(1, tr("Steps by path"));
    tapes_->setTabText(0, tr("Path 1"));
    tapes_->setTabText(1, tr("Path 2"));
}

void StationWindow::buildMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New"), QKeySequence::New, files_, &FileActions::newJob);
    file->addAction(tr("&Open…"), QKeySequence::Open, files_, &FileActions::open);
    QMenu* recent = file->addMenu(tr("Open &recent"));
    connect(recent, &QMenu::aboutToShow, this, [this, recent] { files_->fillRecentMenu(recent); });
    file->addAction(tr("&Import turned part (STEP)…"), files_, &FileActions::importStep);
    file->addAction(tr("Import s&urface (STEP face set)…"), files_, &FileActions::importSurface);
    file->addAction(tr("Import &DXF contours…"), this, &StationWindow::importDxf)->setObjectName("action.importDxf");
    file->addAction(tr("&Save"), QKeySequence::Save, files_, &FileActions::save);
    file->addAction(tr("Save &as…"), QKeySequence::SaveAs, files_, &FileActions::saveAs);
    // The shop server's job store (docs/shop-server.md), when the tool setting names a server.
    QAction* fromStore = file->addAction(tr("Open from the s&hop server…"), files_->store(), &StoreActions::openFromStore);
    fromStore->setObjectName("action.openFromStore");
    QAction* toStore = file->addAction(tr("Save to the shop ser&ver"), files_->store(), &StoreActions::saveToStore);
    toStore->setObjectName("action.saveToStore");
    fromStore->setEnabled(StoreActions::available());
    toStore->setEnabled(StoreActions::available());
    file->addSeparator();
    file->addAction(tr("&Export tape and sheet…"), QKeySequence(tr("Ctrl+E")), files_, &FileActions::exportJob);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    // Owned by the menu bar: a language switch makes them anew.
    QAction* undo = doc_->undoStack()->createUndoAction(menuBar(), tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = doc_->undoStack()->createRedoAction(menuBar(), tr("&Redo"));
    redo->setShortcuts({QKeySequence(tr("Ctrl+Shift+Z")), QKeySequence(tr("Ctrl+Y"))});
    edit->addAction(undo);
    edit->addAction(redo);

    QMenu* job = menuBar()->addMenu(tr("&Job"));
    // The machine's modules only (onDocumentChanged shows them); Ctrl+4 and
    // Ctrl+3 add an M4 and an M2D unit (docs/station.md, Keyboard).
    for (const ModuleKind* kind : moduleKinds()) {
        const QString name = QString::fromUtf8(kind->name());
        QAction* a = job->addAction(QCoreApplication::translate("taiwa::ui::ModulePalette", kind->paletteText()), this,
                                    [this, name] { addUnit(name); });
        a->setObjectName("action.add" + name);
        a->setProperty("machineKind", static_cast<int>(kind->machineKind()));
        if (name == "M4") a->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_4));
        if (name == "M2D") a->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_3));
    }
    job->addSeparator();
    job->addAction(tr("&Technology data…"), QKeySequence(tr("Ctrl+T")), this, &StationWindow::editTechnology);
    job->addAction(tr("Tool &library…"), QKeySequence(tr("Ctrl+L")), this, &StationWindow::showToolLibrary);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    // What the 3-D view draws: the same switches as under the step list,
    // each kept in step with its box there.
    const auto mirror = [this, view](const char* name, const QString& text, bool (StepPanel::*shown)() const,
                                     void (StepPanel::*set)(bool), void (StepPanel::*toggled)(bool)) {
        QAction* a = view->addAction(text);
        a->setObjectName(name);
        a->setCheckable(true);
        a->setChecked((steps_->*shown)());
        connect(a, &QAction::toggled, steps_, set);
        connect(steps_, toggled, a, &QAction::setChecked);
    };
    mirror("menu.view.paths", tr("Tool &paths"), &StepPanel::pathsShown, &StepPanel::setPathsShown, &StepPanel::showPathsToggled);
    mirror("menu.view.stock", tr("&Stock as cut"), &StepPanel::stockShown, &StepPanel::setStockShown, &StepPanel::showStockToggled);
    if (preview_) {
        QAction* part = view->addAction(tr("Pa&rt"));
        part->setObjectName("menu.view.part");
        part->setCheckable(true);
        part->setChecked(preview_->scene().partShown());
        part->setToolTip(tr("The finished pockets' outlines, or the turned part"));
        connect(part, &QAction::toggled, preview_, &PreviewWidget::setPartShown);
    }
    QAction* frame = view->addAction(tr("&Zoom to the selected step"), steps_, [this] { emit steps_->viewRequested(ViewButton::Step); });
    frame->setObjectName("menu.view.frameStep");
    view->addSeparator();
    QMenu* language = view->addMenu(tr("&Language"));
    auto* group = new QActionGroup(language);
    for (const auto& [code, name] : availableLanguages()) {
        QAction* a = language->addAction(name);
        a->setCheckable(true);
        a->setChecked(code == savedLanguage());
        group->addAction(a);
        a->setObjectName("language." + code);
        // At once: every panel is told (QEvent::LanguageChange, changeEvent).
        connect(a, &QAction::triggered, this, [this, code = code, name = name] {
            if (!switchLanguage(code)) statusBar()->showMessage(tr("No translation for %1: English is shown.").arg(name), 8000);
        });
    }
    // The grid the 3-D view simulates the stock on: finer shows more, takes
    // longer after each change. Kept across sessions.
    QMenu* grid = view->addMenu(tr("Stock &grid"));
    grid->setObjectName("menu.stockGrid");
    auto* grids = new QActionGroup(grid);
    const int saved = std::clamp(QSettings().value("preview/stockGrid", 1).toInt(), 0, int(std::size(sim::kStockGrids)) - 1);
    runner_->setStockGrid(sim::kStockGrids[saved]);
    const QString names[] = {tr("Fine: %1 mm, up to %2 cells"), tr("Standard: %1 mm, up to %2 cells"),
                             tr("Coarse: %1 mm, up to %2 cells")};
    for (int k = 0; k < int(std::size(sim::kStockGrids)); ++k) {
        const sim::StockGrid g = sim::kStockGrids[k];
        QAction* a = grid->addAction(names[k].arg(g.finest).arg(QLocale().toString(qulonglong(g.maxCells))));
        a->setObjectName(QStringLiteral("stockGrid.%1").arg(k));
        a->setCheckable(true);
        a->setChecked(k == saved);
        grids->addAction(a);
        connect(a, &QAction::triggered, this, [this, k, g] {
            QSettings().setValue("preview/stockGrid", k);
            runner_->setStockGrid(g);
            // What this job's stock gets: the grid is coarser on a stock too large for its cells.
            const double cell = sim::HeightField::cellSizeFor(doc_->job().stock, g.maxCells, g.finest);
            statusBar()->showMessage(tr("Stock grid: %1 mm cells on this stock").arg(cell, 0, 'g', 3), 8000);
        });
    }
}

}  // namespace taiwa::ui
