// The unit forms in the centre column's scroll area: one shown at a time,
// the stack as wide and as high as the form shown (its height for the width
// it gets: wrapped rows, wrapped error texts), not as its largest form as a
// QStackedWidget would be (issue 34, item 2).
#pragma once

#include <QWidget>

class QVBoxLayout;

namespace taiwa::ui {

class FormStack : public QWidget {
    Q_OBJECT
public:
    explicit FormStack(QWidget* parent = nullptr);
    void addWidget(QWidget* page);
    // Shows `page` and hides every other.
    void setCurrentWidget(QWidget* page);
    QWidget* currentWidget() const { return current_; }
    QWidget* widget(int i) const;
    int count() const;

private:
    QVBoxLayout* box_;
    QWidget* current_ = nullptr;
};

}  // namespace taiwa::ui
