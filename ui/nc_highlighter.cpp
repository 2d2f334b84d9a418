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

bool NcHighlighter::eventFilter(QObject* watched, QEvent* event)
{
    if (event->type() == QEvent::Resize) colourShownLines();
    return QObject::eventFilter(watched, event);
}

QList<QTextLayout::FormatRange> NcHighlighter::colours(const QString& text) const
{
    static const QRegularExpression word(R"(([A-Za-z])\s*[-+]?[0-9.]+)");
    static const QRegularExpression comment(R"(\([^)]*\)?|;.*$)");
    // Comments first: the words within them are the comment's colour only.
    QList<QTextLayout::FormatRange> out, remarks;
    for (auto it = comment.globalMatch(text); it.hasNext();) {
        const auto hit = it.next();
        remarks.push_back({static_cast<int>(hit.capturedStart()), static_cast<int>(hit.capturedLength()), rem_});
    }
    const auto inRemark = [&](qsizetype at) {
        return std::any_of(remarks.begin(), remarks.end(), [&](const auto& r) { return at >= r.start && at < r.start + r.length; });
    };
    for (auto it = word.globalMatch(text); it.hasNext();) {
        const auto hit = it.next();
        if (inRemark(hit.capturedStart()) || inRemark(hit.capturedEnd() - 1)) continue;
        const QChar c = text.at(hit.capturedStart(1)).toUpper();
        const QTextCharFormat* f = &other_;
        if (c == 'G') f = &g_;
        else if (c == 'M') f = &m_;
        else if (c == 'N' || c == 'O') f = &seq_;
        else if (QStringLiteral("XYZIJKRABC").contains(c)) f = &axis_;
        out.push_back({static_cast<int>(hit.capturedStart()), static_cast<int>(hit.capturedLength()), *f});
    }
    out += remarks;
    return out;
}

}  // namespace taiwa::ui
