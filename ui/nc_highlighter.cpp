// The NC syntax highlighter.
#include "ui/nc_highlighter.h"

#include <QRegularExpression>

namespace taiwa::ui {

NcHighlighter::NcHighlighter(QTextDocument* doc) : QSyntaxHighlighter(doc) {}

void NcHighlighter::highlightBlock(const QString& text)
{
    static const QRegularExpression word(R"(([A-Za-z])\s*[-+]?[0-9.]+)");
    static const QRegularExpression comment(R"(\([^)]*\)?|;.*$)");
    QTextCharFormat g, m, axis, seq, other, rem;
    g.setForeground(QColor("#0040c0"));
    g.setFontWeight(QFont::Bold);
    m.setForeground(QColor("#a000a0"));
    m.setFontWeight(QFont::Bold);
    axis.setForeground(QColor("#006000"));
    seq.setForeground(QColor("#808080"));
    other.setForeground(QColor("#805000"));
    rem.setForeground(QColor("#909090"));
    rem.setFontItalic(true);
    for (auto it = word.globalMatch(text); it.hasNext();) {
        const auto hit = it.next();
        const QChar c = hit.captured(1).at(0).toUpper();
        const QTextCharFormat* f = &other;
        if (c == 'G') f = &g;
        else if (c == 'M') f = &m;
        else if (c == 'N' || c == 'O') f = &seq;
        else if (QStringLiteral("XYZIJKRABC").contains(c)) f = &axis;
        setFormat(static_cast<int>(hit.capturedStart()), static_cast<int>(hit.capturedLength()), *f);
    }
    for (auto it = comment.globalMatch(text); it.hasNext();) {
        const auto hit = it.next();
        setFormat(static_cast<int>(hit.capturedStart()), static_cast<int>(hit.capturedLength()), rem);
    }
}

}  // namespace taiwa::ui
