// The station's DXF import (dxf_import_dialog.h).
#include "ui/dxf_import_dialog.h"

#include "ui/core_messages.h"

#include "dxf/dxf_import.h"
#include "figure/figure_units.h"
#include "figure/figure_from_contours.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontDatabase>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace taiwa::ui {

DxfImportDialog::DxfImportDialog(const Job& job, QWidget* parent) : QDialog(parent), job_(job)
{
    setWindowTitle(tr("Import DXF"));
    setObjectName("dxf");
    auto* box = new QVBoxLayout(this);
    auto* fileRow = new QHBoxLayout;
    file_ = new QLabel(tr("No drawing chosen"), this);
    file_->setObjectName("dxf.file");
    auto* choose = new QPushButton(tr("Choose…"), this);
    choose->setObjectName("dxf.choose");
    fileRow->addWidget(file_, 1);
    fileRow->addWidget(choose);
    box->addLayout(fileRow);
    auto* form = new QFormLayout;
    layers_ = new QListWidget(this);
    layers_->setObjectName("dxf.layers");
    layers_->setMaximumHeight(120);
    layers_->setToolTip(tr("The layers whose lines, arcs, circles, polylines and splines are imported"));
    form->addRow(tr("Layers"), layers_);
    gap_ = new QDoubleSpinBox(this);
    gap_->setObjectName("dxf.gap");
    gap_->setLocale(QLocale::c());
    gap_->setDecimals(3);
    gap_->setRange(0.001, 5.0);
    gap_->setSingleStep(0.01);
    gap_->setValue(0.01);
    gap_->setSuffix(QStringLiteral(" mm"));
    gap_->setKeyboardTracking(false);
    gap_->setToolTip(tr("Ends at most this far apart are joined into one contour; wider gaps are reported"));
    form->addRow(tr("Gap tolerance"), gap_);
    box->addLayout(form);
    report_ = new QPlainTextEdit(this);
    report_->setObjectName("dxf.report");
    report_->setReadOnly(true);
    report_->setMaximumHeight(140);
    box->addWidget(new QLabel(tr("What the drawing gives"), this));
    box->addWidget(report_);
    preview_ = new QPlainTextEdit(this);
    preview_->setObjectName("dxf.text");
    preview_->setReadOnly(true);
    preview_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    preview_->setLineWrapMode(QPlainTextEdit::NoWrap);
    box->addWidget(new QLabel(tr("Figure elements to add"), this));
    box->addWidget(preview_, 1);
    buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons_->setObjectName("dxf.buttons");
    buttons_->button(QDialogButtonBox::Ok)->setText(tr("Import"));
    buttons_->button(QDialogButtonBox::Ok)->setEnabled(false);
    box->addWidget(buttons_);
    resize(640, 620);

    connect(choose, &QPushButton::clicked, this, &DxfImportDialog::choose);
    connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(layers_, &QListWidget::itemChanged, this, [this] {
        if (!reading_) read(false);
    });
    connect(gap_, &QDoubleSpinBox::valueChanged, this, [this] {
        if (!reading_) read(false);
    });
}

void DxfImportDialog::choose()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Import DXF"), QFileInfo(path_).path(),
                                                      tr("DXF drawings (*.dxf *.DXF)"));
    if (!path.isEmpty()) setPath(path);
}

void DxfImportDialog::setPath(const QString& path)
{
    path_ = path;
    file_->setText(QFileInfo(path).fileName());
    file_->setToolTip(path);
    read(true);
}

QString DxfImportDialog::report() const { return report_->toPlainText(); }

std::string DxfImportDialog::appendedTo(const std::string& figure) const
{
    if (text_.empty()) return figure;
    if (figure.empty()) return text_;
    return figure + (figure.back() == '\n' ? "" : "\n") + text_;
}

// The drawing read again with the layers ticked (all of the file's when it
// is new) and the gap tolerance; the report and the text anew.
void DxfImportDialog::read(bool layersFromFile)
{
    reading_ = true;
    dxf::DxfOptions options;
    options.gapTolerance = gap_->value();
    if (!layersFromFile)
        for (int i = 0; i < layers_->count(); ++i)
            if (layers_->item(i)->checkState() == Qt::Checked) options.layers.push_back(layers_->item(i)->text().toStdString());
    const bool none = !layersFromFile && options.layers.empty();
    const dxf::DxfReadResult r = dxf::readDxf(path_.toStdString(), options);
    if (layersFromFile) {
        layers_->clear();
        for (const dxf::LayerInfo& l : r.layers) {
            auto* item = new QListWidgetItem(QString::fromStdString(l.name), layers_);
            item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
            item->setCheckState(Qt::Checked);
            item->setToolTip(tr("%1 entities").arg(l.entities));
        }
    }
    QStringList lines;
    text_.clear();
    if (!r.ok()) {
        lines << tr("Refused: %1").arg(coreMessage(*r.error));
    } else if (none) {
        lines << tr("No layer is ticked.");
    } else {
        lines << tr("%1 closed and %2 open contours, drawn in %3.")
                     .arg(r.closedCount())
                     .arg(r.openCount())
                     .arg(coreMessage(r.units));
        if (r.smallGapsClosed > 0)
            lines << tr("%1 ends joined over gaps within the tolerance; the largest %2 mm.")
                         .arg(r.smallGapsClosed)
                         .arg(r.largestGapClosed, 0, 'g', 3);
        for (const auto& g : r.gaps) lines << tr("Gap: %1").arg(coreMessage(g.message));
        for (const auto& b : r.branches) lines << tr("Branch: %1").arg(coreMessage(b.message));
        std::vector<Contour> contours;
        for (const auto& c : r.contours) contours.push_back(c.contour);
        FigureNaming naming;
        naming.taken = figureNames(job_.figure);
        const FigureFromContours f = figureFromContours(contours, naming);
        for (const auto& n : f.notes) lines << coreMessage(n);
        for (const auto& x : f.refusals) lines << coreMessage(x);
        // The figure is in mm here; the job's text is in its own unit.
        text_ = job_.lengthUnit == LengthUnit::Inch
                    ? figure::convertFigureLengths(f.text, [](double v) { return v / 25.4; })
                    : f.text;
    }
    for (const auto& w : r.warnings) lines << coreMessage(w);
    report_->setPlainText(lines.join('\n'));
    preview_->setPlainText(QString::fromStdString(text_));
    buttons_->button(QDialogButtonBox::Ok)->setEnabled(!text_.empty());
    reading_ = false;
}

}  // namespace taiwa::ui
