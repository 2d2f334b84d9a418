// The NC view's colours (ui/nc_highlighter.*): the lines shown are coloured
// as the tape's words are (G and M bold blue and purple, axis words green,
// comments grey italic, the words inside a comment too), lines far below
// are not coloured until scrolled to, and then they are.
#include "ui/nc_highlighter.h"
#include "ui/nc_view.h"

#include <QApplication>
#include <QPlainTextEdit>
#include <QScrollBar>
#include <QTextBlock>
#include <QTextLayout>
#include <QtTest>

#include <memory>

using taiwa::BlockSource;
using taiwa::ui::NcView;

namespace {

// The colour and weight at a character of a line, as drawn.
QTextCharFormat formatAt(const QTextBlock& b, int at)
{
    QTextCharFormat f;
    for (const auto& r : b.layout()->formats())
        if (at >= r.start && at < r.start + r.length) f = r.format;
    return f;
}

}  // namespace

class TestGuiNcView : public QObject {
    Q_OBJECT
private slots:
    void coloursTheLinesShownThenTheLinesScrolledTo()
    {
        QString nc = "%\n(T1 G43 in a comment)\n";
        for (int i = 0; i < 20000; ++i) nc += QString("N%1 G1 X%2 Y5. F600 M8\n").arg(i * 10).arg(i);
        nc += "M30\n%";
        const std::vector<BlockSource> lines(static_cast<std::size_t>(nc.count('\n') + 1));
        NcView view;
        view.resize(600, 400);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        view.setProgram(nc, lines);
        QTRY_VERIFY(view.highlighter()->coloured(2));
        QTextDocument* doc = view.text()->document();

        const QTextBlock move = doc->findBlockByNumber(2);  // "N0 G1 X0 Y5. F600 M8"
        const QString t = move.text();
        QCOMPARE(formatAt(move, static_cast<int>(t.indexOf("G1"))).foreground().color(), QColor(0x00, 0x40, 0xc0));
        QCOMPARE(formatAt(move, static_cast<int>(t.indexOf("G1"))).fontWeight(), int(QFont::Bold));
        QCOMPARE(formatAt(move, static_cast<int>(t.indexOf("X0"))).foreground().color(), QColor(0x00, 0x60, 0x00));
        QCOMPARE(formatAt(move, static_cast<int>(t.indexOf("M8"))).foreground().color(), QColor(0xa0, 0x00, 0xa0));
        QCOMPARE(formatAt(move, 0).foreground().color(), QColor(0x80, 0x80, 0x80));  // N
        const QTextBlock remark = doc->findBlockByNumber(1);
        const QTextCharFormat inside = formatAt(remark, static_cast<int>(remark.text().indexOf("G43")));
        QCOMPARE(inside.foreground().color(), QColor(0x90, 0x90, 0x90));
        QVERIFY(inside.fontItalic() && inside.fontWeight() != int(QFont::Bold));

        // Far below: not coloured yet; scrolled to, coloured.
        const int last = doc->blockCount() - 2;
        QVERIFY(!view.highlighter()->coloured(last));
        QVERIFY(formatAt(doc->findBlockByNumber(last), 0).foreground().style() == Qt::NoBrush);
        view.text()->verticalScrollBar()->setValue(view.text()->verticalScrollBar()->maximum());
        QTRY_VERIFY(view.highlighter()->coloured(last));
        QCOMPARE(formatAt(doc->findBlockByNumber(last), 0).foreground().color(), QColor(0xa0, 0x00, 0xa0));  // M30
        QVERIFY(!view.highlighter()->coloured(10000));

        // A new program: its first lines coloured again.
        view.setProgram("G0 X1\nM30\n", std::vector<BlockSource>(3));
        QTRY_VERIFY(view.highlighter()->coloured(0));
        doc = view.text()->document();  // a new program is a new document
        QCOMPARE(formatAt(doc->findBlockByNumber(0), 0).foreground().color(), QColor(0x00, 0x40, 0xc0));
    }

    // Issue 34, item 9: Klartext shown as Klartext. The dialect's data file
    // brings its rules: BLK FORM's M, CYCL DEF's F and TOOL CALL's L are the
    // control's words, not M, F and L addresses; its M, axis and incremental
    // words stay coloured as such; and an ISO tape is coloured as before.
    void klartextColouredByTheDialectsRules()
    {
        const QString nc = "9 BLK FORM 0.1 Z X+0 Y+0 Z-30\n"
                           "14 TOOL CALL 10 Z S3820\n"
                           "15 L X+42.5 Y+37.5 R0 FMAX M3\n"
                           "18 CYCL DEF 200 DRILLING ~\n"
                           "19 L IZ-0.247 FMAX ; TOOL CALL 5 in a comment\n";
        const QColor m(0xa0, 0x00, 0xa0), other(0x80, 0x50, 0x00), axis(0x00, 0x60, 0x00);
        NcView view;
        view.resize(600, 400);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        view.setDialect("heidenhain");
        view.setProgram(nc, std::vector<BlockSource>(6));
        QTRY_VERIFY(view.highlighter()->coloured(4));
        QTextDocument* doc = view.text()->document();
        const auto at = [&](int line, const QString& word, int offset = 0) {
            const QTextBlock b = doc->findBlockByNumber(line);
            const int i = static_cast<int>(b.text().indexOf(word));
            return i < 0 ? QTextCharFormat() : formatAt(b, i + offset);
        };
        const QColor keyword = at(0, "BLK FORM").foreground().color();
        QVERIFY(keyword != m && keyword != other && keyword != axis && at(0, "BLK FORM").foreground().style() != Qt::NoBrush);
        QCOMPARE(at(0, "FORM 0.1", 3).foreground().color(), keyword);  // the M of BLK FORM
        QVERIFY(at(0, "0.1").foreground().color() != m);                // and its number
        QCOMPARE(at(1, "CALL 10", 3).foreground().color(), keyword);  // the L of TOOL CALL
        QVERIFY(at(1, " 10", 1).foreground().color() != other);
        QCOMPARE(at(3, "DEF 200", 2).foreground().color(), keyword);  // the F of CYCL DEF
        QVERIFY(at(3, "200").foreground().color() != other);
        QCOMPARE(at(2, "X+42.5").foreground().color(), axis);
        QCOMPARE(at(2, "M3").foreground().color(), m);
        QCOMPARE(at(2, "FMAX").foreground().color(), keyword);
        QCOMPARE(at(4, "IZ-0.247", 1).foreground().color(), axis);
        QVERIFY(at(4, "TOOL CALL 5").fontItalic());  // in the comment: the comment's colour only
        // The same lines under an ISO dialect's rules: addresses apart from
        // their numbers are addresses there ("M 0.1" of BLK FORM).
        view.setDialect("linuxcnc");
        QTRY_VERIFY(view.highlighter()->coloured(0));
        QCOMPARE(at(0, "FORM 0.1", 3).foreground().color(), m);
        const QTextBlock iso = doc->findBlockByNumber(2);
        QCOMPARE(formatAt(iso, static_cast<int>(iso.text().indexOf("M3"))).foreground().color(), m);
    }

    // A program's text put in on the view's own thread (prepareProgram), then
    // shown: the text is the program's, whichever was prepared last, and a
    // text prepared for another program is not shown for this one.
    void showsTheTextPreparedForIt()
    {
        const auto tape = [](int n, const char* word) {
            QString nc;
            for (int i = 0; i < n; ++i) nc += QString("N%1 %2 X%3\n").arg(i).arg(word).arg(i);
            return nc + "M30";
        };
        const QString a = tape(30000, "G1"), b = tape(30000, "G0"), c = tape(200, "G2");
        NcView view;
        view.resize(600, 400);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));

        view.prepareProgram(a);
        view.setProgram(a, std::vector<BlockSource>(30001));  // made here or there, waited for if being made
        QCOMPARE(view.text()->toPlainText(), a);
        const int before = view.preparedShown();
        view.prepareProgram(b);
        QTRY_VERIFY(view.isPrepared(b));
        QVERIFY(!view.isPrepared(a));
        view.setProgram(b, std::vector<BlockSource>(30001));
        QCOMPARE(view.text()->toPlainText(), b);
        QCOMPARE(view.preparedShown(), before + 1);
        QCOMPARE(view.text()->document()->thread(), view.thread());
        QCOMPARE(view.text()->document()->defaultFont(), view.text()->font());
        QCOMPARE(view.text()->document()->blockCount(), 30001);

        view.prepareProgram(a);  // prepared, then another program came
        QTRY_VERIFY(view.isPrepared(a));
        view.setProgram(c, std::vector<BlockSource>(201));
        QCOMPARE(view.text()->toPlainText(), c);
        QCOMPARE(view.preparedShown(), before + 1);
        view.prepareProgram(c);
        QTRY_VERIFY(view.isPrepared(c));
        view.setProgram(c, std::vector<BlockSource>(201));
        QCOMPARE(view.text()->toPlainText(), c);
        QCOMPARE(view.preparedShown(), before + 2);
        QCOMPARE(view.text()->lineWrapMode(), QPlainTextEdit::NoWrap);

        // The band of the current line and the colours, as for any new text.
        QCOMPARE(view.highlightedLine(), 0);
        QTRY_VERIFY(view.highlighter()->coloured(0));

        // Scrolled to the end of one program, the next shows its first line.
        view.setProgram(b, std::vector<BlockSource>(30001));
        view.text()->verticalScrollBar()->setValue(view.text()->verticalScrollBar()->maximum());
        view.text()->moveCursor(QTextCursor::End);
        QVERIFY(view.text()->verticalScrollBar()->value() > 1000);
        view.prepareProgram(a);
        QTRY_VERIFY(view.isPrepared(a));
        view.setProgram(a, std::vector<BlockSource>(30001));
        QCOMPARE(view.text()->verticalScrollBar()->value(), 0);
        QCOMPARE(view.text()->textCursor().blockNumber(), 0);
        QCOMPARE(view.highlightedLine(), 0);

        view.setMessage("no program");
        QCOMPARE(view.text()->toPlainText(), QString("no program"));
    }

    // A view closed while a text is being made for it (the station closed
    // just after an edit) frees everything without waiting on it for long.
    void closedWhileATextIsMade()
    {
        QString nc;
        for (int i = 0; i < 40000; ++i) nc += QString("N%1 G1 X%2\n").arg(i).arg(i);
        auto view = std::make_unique<NcView>();
        view->setProgram("G0 X0", std::vector<BlockSource>(1));
        view->prepareProgram(nc);
        view.reset();  // fails by a crash or a hang (the test's time-out)
    }
};

QTEST_MAIN(TestGuiNcView)
#include "test_gui_nc_view.moc"
