// The NC syntax highlighter, colouring the lines the view shows.
#include "ui/nc_highlighter.h"

#include <QEvent>
#include <QPlainTextEdit>
#include <QRegularExpression>
#include <QScrollBar>
#include <QTextBlock>

#include <algorithm>

namespace taiwa::ui {

NcHighlighter::NcHighlighter(QPlainTextEdit* view) : QObject(view), view_(view)
{
    g_.setForeground(QColor(0x00, 0x40, 0xc0));
    g_.setFontWeight(QFont::Bold);
    m_.setForeground(QColor(0xa0, 0x00, 0xa0));
    m_.setFontWeight(QFont::Bold);
    axis_.setForeground(QColor(0x00, 0x60, 0x00));
    seq_.setForeground(QColor(0x80, 0x80, 0x80));
    other_.setForeground(QColor(0x80, 0x50, 0x00));
    rem_.setForeground(QColor(0x90, 0x90, 0x90));
    rem_.setFontItalic(true);
    keyword_.setForeground(QColor(0x00, 0x60, 0x80));
    keyword_.setFontWeight(QFont::Bold);
    setRules({});
    // Scrolled, resized, or a new text (the view is read-only: any change is
    // a new program, which shows its first lines).
    connect(view_->verticalScrollBar(), &QScrollBar::valueChanged, this, &NcHighlighter::colourShownLines);
    watch(view_->document());
    view_->viewport()->installEventFilter(this);
}

void NcHighlighter::watch(QTextDocument* doc)
{
    disconnect(changed_);
    disconnect(changedLater_);
    coloured_.clear();
    changed_ = connect(doc, &QTextDocument::contentsChange, this, [this] { coloured_.clear(); });
    changedLater_ = connect(doc, &QTextDocument::contentsChanged, this, &NcHighlighter::colourShownLines,
                            Qt::QueuedConnection);
    QMetaObject::invokeMethod(this, &NcHighlighter::colourShownLines, Qt::QueuedConnection);
}

void NcHighlighter::colourShownLines()
{
    const int line = std::max(1, view_->fontMetrics().lineSpacing());
    const int shown = std::max(60, view_->viewport()->height() / line + 1);
    const int top = view_->cursorForPosition(QPoint(0, 0)).blockNumber();
    QTextDocument* doc = view_->document();
    coloured_.resize(static_cast<std::size_t>(doc->blockCount()), false);
    for (QTextBlock b = doc->findBlockByNumber(std::max(0, top - shown)); b.isValid() && b.blockNumber() <= top + 2 * shown;
         b = b.next()) {
        const auto k = static_cast<std::size_t>(b.blockNumber());
        if (coloured_[k]) continue;
        coloured_[k] = true;
        b.layout()->setFormats(colours(b.text()));
        doc->markContentsDirty(b.position(), b.length());
    }
}

bool NcHighlighter::coloured(int block) const
{
    return block >= 0 && static_cast<std::size_t>(block) < coloured_.size() && coloured_[static_cast<std::size_t>(block)];
}

void NcHighlighter::setRules(const post::Highlighting& rules)
{
    // An address: its letter (Klartext's incremental IX/IZ: the last), a sign
    // and a number; apart from it by spaces only where the dialect allows.
    word_ = QRegularExpression(rules.addressesApart ? QStringLiteral(R"(([A-Za-z])\s*[-+]?[0-9.]+)")
                                                    : QStringLiteral(R"((?<![A-Za-z0-9_])I?([A-Za-z])[-+]?[0-9.]+)"));
    // The keywords, longest first, as whole words ("CALL LBL" before "LBL", "CC" before "C").
    QStringList words;
    for (const std::string& k : rules.keywords) words << QRegularExpression::escape(QString::fromStdString(k));
    std::sort(words.begin(), words.end(), [](const QString& a, const QString& b) { return a.size() > b.size(); });
    keywords_ = QRegularExpression(words.isEmpty() ? QStringLiteral("(?!)")
                                                   : QStringLiteral(R"((?<![A-Za-z0-9_])(?:%1)(?![A-Za-z0-9_]))").arg(words.join('|')));
    coloured_.assign(coloured_.size(), false);
    QMetaObject::invokeMethod(this, &NcHighlighter::colourShownLines, Qt::QueuedConnection);
}

bool NcHighlighter::eventFilter(QObject* watched, QEvent* event)
{
    if (event->type() == QEvent::Resize) colourShownLines();
    return QObject::eventFilter(watched, event);
}

QList<QTextLayout::FormatRange> NcHighlighter::colours(const QString& text) const
{
    static const QRegularExpression comment(R"(\([^)]*\)?|;.*$)");
    // Comments first: the words within them are the comment's colour only.
    QList<QTextLayout::FormatRange> out, remarks;
    for (auto it = comment.globalMatch(text); it.hasNext();) {
        const auto hit = it.next();
        remarks.push_back({static_cast<int>(hit.capturedStart()), static_cast<int>(hit.capturedLength()), rem_});
    }
    const auto inside = [](const QList<QTextLayout::FormatRange>& ranges, qsizetype at) {
        return std::any_of(ranges.begin(), ranges.end(), [&](const auto& r) { return at >= r.start && at < r.start + r.length; });
    };
    const auto inRemark = [&](qsizetype at) { return inside(remarks, at); };
    // The control's own words, outside comments: neither their letters nor
    // the numbers after them are addresses ("BLK FORM 0.1", "TOOL CALL 10").
    QList<QTextLayout::FormatRange> keywords;
    for (auto it = keywords_.globalMatch(text); it.hasNext();) {
        const auto hit = it.next();
        if (inRemark(hit.capturedStart())) continue;
        keywords.push_back({static_cast<int>(hit.capturedStart()), static_cast<int>(hit.capturedLength()), keyword_});
    }
    for (auto it = word_.globalMatch(text); it.hasNext();) {
        const auto hit = it.next();
        if (inRemark(hit.capturedStart()) || inRemark(hit.capturedEnd() - 1)) continue;
        if (inside(keywords, hit.capturedStart()) || inside(keywords, hit.capturedEnd() - 1)) continue;
        const QChar c = text.at(hit.capturedStart(1)).toUpper();
        const QTextCharFormat* f = &other_;
        if (c == 'G') f = &g_;
        else if (c == 'M') f = &m_;
        else if (c == 'N' || c == 'O') f = &seq_;
        else if (QStringLiteral("XYZIJKRABC").contains(c)) f = &axis_;
        out.push_back({static_cast<int>(hit.capturedStart()), static_cast<int>(hit.capturedLength()), *f});
    }
    out += keywords;
    out += remarks;
    return out;
}

}  // namespace taiwa::ui
