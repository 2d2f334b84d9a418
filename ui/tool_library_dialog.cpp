// The tool library dialog.
#include "ui/tool_library_dialog.h"

#include "tools/tool_library.h"
#include "ui/number_text.h"

#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace taiwa::ui {
namespace {
QString num(double v) { return formatNumber(std::round(v * 1000.0) / 1000.0); }
}  // namespace

ToolLibraryDialog::ToolLibraryDialog(QWidget* parent)
    : QDialog(parent), table_(new QTableWidget(this)), status_(new QLabel(this)),
      reset_(new QPushButton(tr("&Reset wear of the selected tool"), this))
{
    setWindowTitle(tr("Tool library"));
    table_->setObjectName("tools");
    table_->setColumnCount(10);
    table_->setHorizontalHeaderLabels({tr("T"), tr("Name"), tr("Type"), tr("Ø mm"), tr("Corner r"), tr("Taper °"),
                                       tr("Flute mm"), tr("Holder"), tr("Life min"), tr("Used min")});
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->verticalHeader()->hide();
    table_->horizontalHeader()->setStretchLastSection(true);
    status_->setWordWrap(true);
    reset_->setObjectName("tools.resetWear");
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(reset_, &QPushButton::clicked, this, &ToolLibraryDialog::resetWear);
    auto* row = new QHBoxLayout;
    row->addWidget(reset_);
    row->addStretch(1);
    row->addWidget(buttons);
    auto* box = new QVBoxLayout(this);
    box->addWidget(table_, 1);
    box->addWidget(status_);
    box->addLayout(row);
    resize(900, 520);
    load();
}

void ToolLibraryDialog::load()
{
    const std::string path = defaultToolLibraryPath();
    const auto tools = readToolLibrary(path);
    tools_ = tools ? *tools : std::vector<Tool>{};
    status_->setText(tools ? tr("%1 — %n tool(s)", "", static_cast<int>(tools_.size())).arg(QString::fromStdString(path))
                           : tr("Cannot read the tool library: %1").arg(QString::fromStdString(tools.error())));
    status_->setStyleSheet(tools ? QString() : QStringLiteral("color: #a00000;"));
    reset_->setEnabled(tools.ok());
    table_->setRowCount(static_cast<int>(tools_.size()));
    for (std::size_t i = 0; i < tools_.size(); ++i) {
        const Tool& t = tools_[i];
        const QStringList cells{QString::number(t.id),
                                QString::fromStdString(t.name),
                                QString::fromUtf8(toString(t.type)),
                                num(t.diameter),
                                num(t.cornerRadius),
                                num(t.taperAngle),
                                num(t.fluteLength),
                                QString::fromStdString(t.holder),
                                num(t.lifeMinutes),
                                num(t.usedMinutes)};
        for (int c = 0; c < cells.size(); ++c) table_->setItem(static_cast<int>(i), c, new QTableWidgetItem(cells[c]));
    }
    table_->resizeColumnsToContents();
}

void ToolLibraryDialog::resetWear()
{
    const auto rows = table_->selectionModel()->selectedRows();
    if (rows.isEmpty()) {
        status_->setText(tr("Select a tool first."));
        return;
    }
    Tool t = tools_[static_cast<std::size_t>(rows.first().row())];
    t.usedMinutes = 0.0;
    auto lib = ToolLibrary::open(defaultToolLibraryPath());
    const Result<int> saved = lib ? lib->save(t) : Result<int>(Failure{lib.error()});
    if (!saved) {
        status_->setText(tr("Cannot save the tool: %1").arg(QString::fromStdString(saved.error())));
        status_->setStyleSheet(QStringLiteral("color: #a00000;"));
        return;
    }
    changed_ = true;
    const int row = rows.first().row();
    load();
    table_->selectRow(row);
}

}  // namespace taiwa::ui
