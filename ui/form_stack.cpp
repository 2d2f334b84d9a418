// The unit forms' stack: a box layout of pages of which one is visible
// (a box layout leaves hidden widgets out of its size and height for width).
#include "ui/form_stack.h"

#include <QVBoxLayout>

namespace taiwa::ui {

FormStack::FormStack(QWidget* parent) : QWidget(parent), box_(new QVBoxLayout(this))
{
    box_->setContentsMargins(0, 0, 0, 0);
}

void FormStack::addWidget(QWidget* page)
{
    box_->addWidget(page);
    if (!current_) current_ = page;
    else page->hide();
}

void FormStack::setCurrentWidget(QWidget* page)
{
    if (page == current_ || box_->indexOf(page) < 0) return;
    if (current_) current_->hide();
    current_ = page;
    page->show();
}

QWidget* FormStack::widget(int i) const
{
    QLayoutItem* item = box_->itemAt(i);
    return item ? item->widget() : nullptr;
}

int FormStack::count() const { return box_->count(); }

}  // namespace taiwa::ui
