// The tool library dialog (tool_library_dialog.h): the table of the
// library's tools, edited in place, copied, retired, their wear reset, and
// the tool table exported for the control. How a change is saved and
// undone: tool_library_saving.cpp.
#include "ui/tool_library_dialog.h"
#include "ui/core_messages.h"

#include "post/tool_table.h"
#include "tools/tool_check.h"
#include "tools/tool_library.h"
#include "tools/tool_store.h"
#include "ui/number_text.h"

#include <QDialogButtonBox>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeySequence>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSaveFile>
#include <QShortcut>
#include <QTableWidget>
#include <QUndoCommand>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace taiwa::ui {

QString ToolLibraryDialog::num(double v)
{
    return formatNumber(std::round(v * 1000.0) / 1000.0);
}

ToolLibraryDialog::ToolLibraryDialog(QWidget* parent)
    : QDialog(parent), table_(new QTableWidget(this)), status_(new QLabel(this)),
      reset_(new QPushButton(tr("&Reset wear"), this)), undo_(new QUndoStack(this))
{
    setWindowTitle(tr("Tool library"));
    table_->setObjectName("tools");
    table_->setColumnCount(ColumnCount);
    table_->setHorizontalHeaderLabels({tr("T"), tr("Name"), tr("Type"), tr("Ø mm"), tr("Corner r"), tr("Taper °"),
                                       tr("Flutes"), tr("Flute mm"), tr("Stick-out mm"), tr("Holder"), tr("Holder Ø mm"), tr("Life min"),
                                       tr("Used min")});
    table_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                            QAbstractItemView::AnyKeyPressed);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->verticalHeader()->hide();
    table_->horizontalHeader()->setStretchLastSection(true);
    connect(table_, &QTableWidget::itemChanged, this, &ToolLibraryDialog::onItemChanged);
    status_->setObjectName("tools.status");
    status_->setWordWrap(true);
    reset_->setObjectName("tools.resetWear");
    auto* copy = new QPushButton(tr("&Copy"), this);
    copy->setObjectName("tools.copy");
    auto* retire = new QPushButton(tr("Re&tire"), this);
    retire->setObjectName("tools.retire");
    auto* undo = new QPushButton(tr("&Undo"), this);
    undo->setObjectName("tools.undo");
    undo->setEnabled(false);
    auto* exportTable = new QPushButton(tr("&Export tool table…"), this);
    exportTable->setObjectName("tools.export");
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(reset_, &QPushButton::clicked, this, &ToolLibraryDialog::resetWear);
    connect(copy, &QPushButton::clicked, this, &ToolLibraryDialog::copySelected);
    connect(retire, &QPushButton::clicked, this, &ToolLibraryDialog::retireSelected);
    connect(undo, &QPushButton::clicked, undo_, &QUndoStack::undo);
    connect(undo_, &QUndoStack::canUndoChanged, undo, &QPushButton::setEnabled);
    connect(new QShortcut(QKeySequence::Undo, this), &QShortcut::activated, undo_, &QUndoStack::undo);
    connect(new QShortcut(QKeySequence::Redo, this), &QShortcut::activated, undo_, &QUndoStack::redo);
    connect(exportTable, &QPushButton::clicked, this, &ToolLibraryDialog::exportAsked);
    auto* row = new QHBoxLayout;
    for (QPushButton* b : {copy, retire, reset_, undo, exportTable}) row->addWidget(b);
    row->addStretch(1);
    row->addWidget(buttons);
    auto* box = new QVBoxLayout(this);
    box->addWidget(table_, 1);
    box->addWidget(status_);
    box->addLayout(row);
    resize(1100, 560);
    load();
}

ToolLibraryDialog::~ToolLibraryDialog() = default;

QString ToolLibraryDialog::status() const { return status_->text(); }

void ToolLibraryDialog::load(bool keepStatus)
{
    std::string path = defaultToolLibraryPath();
    Result<std::vector<Tool>> tools = Failure{""};
    if (!isServerSetting(path)) {
        tools = readToolLibrary(path);
    } else {  // the shop server: the tools with the versions they were read at
        if (!server_) {
            auto opened = openToolStore(path);
            if (opened) server_ = std::move(*opened);
            else tools = Failure{opened.error()};
        }
        if (server_) {
            path = server_->status();
            auto read = server_->versionedTools();
            if (read) {
                versions_.clear();
                std::vector<Tool> plain;
                for (auto& v : *read) {
                    versions_[v.tool.id] = v.version;
                    plain.push_back(std::move(v.tool));
                }
                tools = std::move(plain);
            } else {
                tools = Failure{read.error()};
            }
        }
    }
    tools_ = tools ? *tools : std::vector<Tool>{};
    knowToolNames(tools_);
    if (!keepStatus || !tools) {
        status_->setText(tools ? tr("%1 — %n tool(s)", "", static_cast<int>(tools_.size())).arg(coreMessage(path))
                               : tr("Cannot read the tool library: %1").arg(coreMessage(tools.error())));
        status_->setStyleSheet(tools ? QString() : QStringLiteral("color: #a00000;"));
    }
    reset_->setEnabled(tools.ok());
    filling_ = true;
    table_->setRowCount(static_cast<int>(tools_.size()));
    for (std::size_t i = 0; i < tools_.size(); ++i) {
        const Tool& t = tools_[i];
        // A built-in holder's name in the station's language (its codes kept), the shop's own as typed.
        const QStringList cells{QString::number(t.id),     localToolName(t),
                                toolKind(t.type),          num(t.diameter),
                                num(t.cornerRadius),       num(t.taperAngle),
                                QString::number(t.flutes), num(t.fluteLength),
                                num(t.stickout),           coreMessage(t.holder),
                                num(t.holderDiameter),     num(t.lifeMinutes),
                                num(t.usedMinutes)};
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            if (c == Id || c == Type || c == Used) item->setFlags(item->flags() & ~Qt::ItemIsEditable);
            if (c != Name && c != Type && c != Holder) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            table_->setItem(static_cast<int>(i), c, item);
        }
    }
    filling_ = false;
    table_->resizeColumnsToContents();
}

void ToolLibraryDialog::fail(const QString& message)
{
    status_->setText(message);
    status_->setStyleSheet(QStringLiteral("color: #a00000;"));
}

int ToolLibraryDialog::selectedRow() const
{
    const auto rows = table_->selectionModel()->selectedRows();
    return rows.isEmpty() ? -1 : rows.first().row();
}

std::optional<Tool> ToolLibraryDialog::selectedTool()
{
    const int row = selectedRow();
    if (row < 0 || row >= static_cast<int>(tools_.size())) {
        fail(tr("Select a tool first."));
        return std::nullopt;
    }
    return tools_[static_cast<std::size_t>(row)];
}

void ToolLibraryDialog::onItemChanged(QTableWidgetItem* item)
{
    if (filling_) return;
    const auto row = static_cast<std::size_t>(item->row());
    if (row >= tools_.size()) return;
    const Tool before = tools_[row];
    Tool after = before;
    const QString text = item->text().trimmed();
    const auto number = parseNumber(text);
    bool ok = true;
    switch (item->column()) {
    case Name:
        // Named by the shop: its own name in every language.
        after.name = text.toStdString();
        after.names.clear();
        break;
    case Holder: after.holder = text.toStdString(); break;
    case Diameter: ok = number.has_value(), after.diameter = number.value_or(0); break;
    case Corner: ok = number.has_value(), after.cornerRadius = number.value_or(0); break;
    case Taper: ok = number.has_value(), after.taperAngle = number.value_or(0); break;
    case FluteLength: ok = number.has_value(), after.fluteLength = number.value_or(0); break;
    case Stickout: ok = number.has_value(), after.stickout = number.value_or(0); break;
    case HolderDiameter: ok = number.has_value(), after.holderDiameter = number.value_or(0); break;
    case Life: ok = number.has_value(), after.lifeMinutes = number.value_or(0); break;
    case Flutes:
        ok = number && *number == std::floor(*number) && std::abs(*number) < 1000;
        after.flutes = ok ? static_cast<int>(*number) : 0;
        break;
    default: return;
    }
    const QString header = table_->horizontalHeaderItem(item->column())->text();
    // Put back once the editor has closed (it still owns the cell now).
    const auto putBack = [this] { QMetaObject::invokeMethod(this, [this] { load(true); }, Qt::QueuedConnection); };
    if (!ok) {
        fail(tr("T%1 not saved: %2 '%3' is not a number").arg(before.id).arg(header, text));
        putBack();
        return;
    }
    if (after == before) return;
    QMetaObject::invokeMethod(
        this,
        [this, before, after, header] {
            if (!change(before, after, tr("T%1: %2 changed").arg(before.id).arg(header))) load(true);
        },
        Qt::QueuedConnection);
}

void ToolLibraryDialog::copySelected()
{
    const auto selected = selectedTool();
    if (!selected) return;
    Tool copy = *selected;
    int id = 1;
    for (const Tool& t : tools_) id = std::max(id, t.id + 1);
    if (id > kMaxToolNumber) {
        fail(tr("No free T number: the library uses T%1").arg(kMaxToolNumber));
        return;
    }
    copy.id = id;
    copy.name += " (copy)";
    copy.names.clear();
    copy.usedMinutes = 0.0;
    change(std::nullopt, copy, tr("T%1 copied to T%2").arg(selected->id).arg(id));
}

void ToolLibraryDialog::retireSelected()
{
    if (const auto t = selectedTool()) change(*t, std::nullopt, tr("T%1 retired (Undo brings it back)").arg(t->id));
}

void ToolLibraryDialog::resetWear()
{
    const auto before = selectedTool();
    if (!before) return;
    Tool after = *before;
    after.usedMinutes = 0.0;
    change(before, after, tr("T%1: wear reset").arg(before->id));
}

bool ToolLibraryDialog::exportToolTable(const QString& path, bool fanuc)
{
    const std::string text = fanuc ? fanucOffsetProgram(tools_, LengthUnit::Millimetre)
                                   : linuxcncToolTable(tools_, LengthUnit::Millimetre);
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(text.data(), static_cast<qint64>(text.size())) < 0 || !file.commit()) {
        fail(tr("Cannot write %1: %2").arg(path, file.errorString()));
        return false;
    }
    status_->setText(tr("Tool table written to %1").arg(path));
    status_->setStyleSheet({});
    return true;
}

void ToolLibraryDialog::exportAsked()
{
    const QString linuxcnc = tr("LinuxCNC tool table (*.tbl)"), fanuc = tr("FANUC offset program, G10 (*.nc)");
    QString chosen;
    const QString path = QFileDialog::getSaveFileName(this, tr("Export tool table"), QStringLiteral("tool.tbl"),
                                                      linuxcnc + ";;" + fanuc, &chosen);
    if (path.isEmpty()) return;
    exportToolTable(path, chosen == fanuc);
}

}  // namespace taiwa::ui
