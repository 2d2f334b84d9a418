// The job's own inputs: name, material, length unit (switching converts
// every length), the machine and its stock (a block: width, length, height;
// a lathe's bar: diameter, length, face stock, bore), how a block is held
// (the vice's jaws on its X or Y faces up to a height: the sheet's setup);
// each change is one undoable edit, numbers parsed as in the unit forms.
#pragma once

#include "model/diagnostic.h"

#include <QWidget>

class QComboBox;
class QFormLayout;
class QLineEdit;

namespace taiwa::ui {

class JobDocument;

class JobProperties : public QWidget {
    Q_OBJECT
public:
    explicit JobProperties(JobDocument* doc, QWidget* parent = nullptr);
    // Shows the job's values (force: also over text that is not a number).
    void refresh(bool force);
    // Marks the stock/material widgets the job-level diagnostics name.
    void showDiagnostics(const Diagnostics& jobLevel);

protected:
    // The language switched: its labels and choices in the new one.
    void changeEvent(QEvent* e) override;

private:
    // The labels, the choices' words and the tips, in the language in force.
    void nameFields();
    void editStock(int which, const QString& text);
    void editJaws(const QString& text);
    JobDocument* doc_;
    QLineEdit* name_;
    QComboBox* material_;
    QComboBox* unit_;
    QLineEdit* stock_[4];  // block: width, length, height; bar: diameter, length, face, bore
    bool bad_[4] = {false, false, false, false};
    QComboBox* machine_ = nullptr;
    QComboBox* vice_;       // no clamping given, jaws on the X faces, on the Y faces
    QLineEdit* jaws_;       // the jaws' height from the block's bottom
    bool badJaws_ = false;
    QFormLayout* form_ = nullptr;
};

}  // namespace taiwa::ui
