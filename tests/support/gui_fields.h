// Finding and typing into the station's form fields in GUI tests (QTest on
// the offscreen platform): by objectName, with the keyboard as an operator
// would.
#pragma once

#include <QApplication>
#include <QLabel>
#include <QTableWidget>
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
    // Opens a table cell's editor with F2 as an operator would, types `text`
    // over what it holds (empty: clears it) and commits it with Return; the
    // window must be shown and active (the editor takes the focus). Returns
    // whether an editor opened. Return commits on the next turn of the event
    // loop and a table may act on the commit a turn later: three are run.
    static bool typeIntoCell(QTableWidget* table, int row, int column, const QString& text)
    {
        table->setFocus();
        table->setCurrentCell(row, column);
        QTest::keyClick(table, Qt::Key_F2);
        auto* editor = qobject_cast<QLineEdit*>(QApplication::focusWidget());
        if (!editor || !table->isAncestorOf(editor)) return false;
        editor->selectAll();
        QTest::keyClick(editor, Qt::Key_Backspace);
        QTest::keyClicks(editor, text);
        QTest::keyClick(editor, Qt::Key_Return);
        for (int turn = 0; turn < 3; ++turn) QCoreApplication::processEvents();
        return true;
    }
};

}  // namespace taiwa::test
