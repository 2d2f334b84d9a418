// The station's export dialog (export_dialog.h).
#include "ui/export_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>

namespace taiwa::ui {

namespace {
const char* const kFolderKey = "export/folder";
const char* const kPicturesKey = "export/pictures";
}  // namespace

ExportDialog::ExportDialog(const ExportChoice& initial, const QStringList& dialects, QWidget* parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("export"));
    setWindowTitle(tr("Export tape and sheet"));
    auto* form = new QFormLayout;
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);

    folder_ = new QLineEdit(initial.folder, this);
    folder_->setObjectName(QStringLiteral("export.folder"));
    folder_->setPlaceholderText(tr("the folder the files are written into"));
    auto* choose = new QPushButton(tr("Choose…"), this);
    choose->setObjectName(QStringLiteral("export.choose"));
    auto* folderRow = new QHBoxLayout;
    folderRow->addWidget(folder_, 1);
    folderRow->addWidget(choose);
    form->addRow(tr("Folder"), folderRow);

    dialect_ = new QComboBox(this);
    dialect_->setObjectName(QStringLiteral("export.dialect"));
    dialect_->addItems(dialects);
    dialect_->setCurrentIndex(std::max(0, static_cast<int>(dialects.indexOf(initial.dialect))));
    form->addRow(tr("Controller dialect"), dialect_);

    units_ = new QComboBox(this);
    units_->setObjectName(QStringLiteral("export.units"));
    units_->addItem(tr("The job's own"));
    units_->addItem(tr("Millimetres"));
    units_->addItem(tr("Inches"));
    units_->setCurrentIndex(!initial.units ? 0 : *initial.units == LengthUnit::Millimetre ? 1 : 2);
    form->addRow(tr("Units"), units_);

    pictures_ = new QCheckBox(tr("The sheet shows the setup and every step in a picture"), this);
    pictures_->setObjectName(QStringLiteral("export.pictures"));
    pictures_->setChecked(initial.pictures);
    form->addRow(tr("Pictures"), pictures_);

    resolution_ = new QDoubleSpinBox(this);
    resolution_->setObjectName(QStringLiteral("export.resolution"));
    resolution_->setDecimals(3);
    resolution_->setRange(0.01, 5.0);
    resolution_->setSingleStep(0.05);
    resolution_->setSuffix(QStringLiteral(" mm"));
    resolution_->setValue(initial.resolution);
    resolution_->setToolTip(tr("The grid the verification cuts the steps into before the files are written: finer finds "
                               "smaller gouges and takes longer."));
    form->addRow(tr("Verification grid"), resolution_);

    buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons_->setObjectName(QStringLiteral("export.buttons"));
    buttons_->button(QDialogButtonBox::Ok)->setText(tr("Export"));
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons_);

    connect(choose, &QPushButton::clicked, this, &ExportDialog::choose);
    connect(folder_, &QLineEdit::textChanged, this, &ExportDialog::updateOk);
    connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
    updateOk();
}

void ExportDialog::choose()
{
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Export into folder"), folder_->text());
    if (!dir.isEmpty()) folder_->setText(QDir::toNativeSeparators(dir));
}

void ExportDialog::updateOk() { buttons_->button(QDialogButtonBox::Ok)->setEnabled(!folder_->text().trimmed().isEmpty()); }

ExportChoice ExportDialog::choice() const
{
    ExportChoice c;
    c.folder = folder_->text().trimmed();
    c.dialect = dialect_->currentText();
    c.units = units_->currentIndex() == 1   ? std::optional(LengthUnit::Millimetre)
              : units_->currentIndex() == 2 ? std::optional(LengthUnit::Inch)
                                            : std::nullopt;
    c.pictures = pictures_->isChecked();
    c.resolution = resolution_->value();
    return c;
}

void ExportDialog::remember(const ExportChoice& c)
{
    QSettings s;
    s.setValue(kFolderKey, QFileInfo(c.folder).absoluteFilePath());
    s.setValue(kPicturesKey, c.pictures);
}

ExportChoice ExportDialog::remembered(ExportChoice c)
{
    QSettings s;
    if (c.folder.isEmpty()) c.folder = s.value(kFolderKey).toString();
    c.pictures = s.value(kPicturesKey, c.pictures).toBool();
    return c;
}

}  // namespace taiwa::ui
