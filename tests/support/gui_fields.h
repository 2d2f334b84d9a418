// Finding and typing into the station's form fields in GUI tests (QTest on
// the offscreen platform): by objectName, with the keyboard as an operator
// would.
#pragma once

#include <QLabel>
#include <QLineEdit>
#include <QTest>
#include <QWidget>

namespace taiwa::test {

struct GuiFields {
    static QLineEdit* edit(QWidget& w, const QString& name)
    {
        auto* e = w.findChild<QLineEdit*>(name);
        if (!e) qWarning("no line edit %s", qPrintable(name));
        return e;
    }
    // The message label under a field.
    static QLabel* label(QWidget& w, const QString& name) { return w.findChild<QLabel*>(name + ".error"); }
    // Selects the field's text and types `text` over it (empty: deletes it).
    static void retype(QLineEdit* e, const QString& text)
    {
        e->setFocus();
        e->selectAll();
        if (text.isEmpty()) QTest::keyClick(e, Qt::Key_Backspace);
        else QTest::keyClicks(e, text);
    }
    static bool isRed(QWidget* e) { return e->styleSheet().contains("#ffd0d0"); }
};

}  // namespace taiwa::test
