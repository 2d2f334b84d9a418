// The sheet's tables on the page painter (page_painter.h): columns of the
// table's widths, a header of two lines repeated on every page, body rows
// as high as their longest wrapped cell drawn as one glyph run per font,
// and where a long table can be cut for a second painter.
#include "export/page_painter.h"

#include <QTextLayout>

#include <algorithm>
#include <numeric>

namespace taiwa::sheetpdf {

std::optional<PagePainter::Cut> PagePainter::cutNearMiddle(const sheet::Table& t)
{
    // The table laid out as table() lays it out: rows of their own
    // heights under a header, a row that does not fit on a fresh page.
    const std::vector<double> x = columns(t);
    const std::size_t half = t.rows.size() / 2;
    double top = y_ + 2 * line_, y = top;
    int page = page_;
    for (std::size_t k = 0; k < t.rows.size(); ++k) {
        const double h = rowHeight(t, k, x);
        if (y + h > area_.height() - line_ && y > top) {
            ++page;
            top = y = 2 * line_;
            if (k >= half) return Cut{k, page};
        }
        y += h;
    }
    return std::nullopt;
}

void PagePainter::table(const sheet::Table& t, std::size_t from, std::size_t to)
{
    to = std::min(to, t.rows.size());
    const std::vector<double> x = columns(t);
    // The header takes two lines, so that "Depth mm" wraps instead of being elided.
    // A header is drawn cell by cell; a body row (as high as its longest
    // wrapped cell) under it as one glyph run per font, and the columns' rules once per page from
    // the header down (a 10,000-unit sheet has 1,000 pages of rows).
    double top = y_;
    const auto rules = [&] {
        for (const double at : x) p_.drawLine(QPointF(at, top), QPointF(at, y_));
    };
    const auto header = [&] {
        const double h = 2 * line_;
        p_.fillRect(QRectF(0, y_, area_.width(), h), QColor(221, 221, 221));
        p_.setFont(bold_);
        for (std::size_t i = 0; i < t.headers.size(); ++i) {
            const QRectF cell(x[i], y_, x[i + 1] - x[i], h);
            p_.drawRect(cell);
            headerText(cell.adjusted(line_ * 0.2, 0, -line_ * 0.2, 0), t.headers[i]);
        }
        p_.setFont(normal_);
        y_ += h;
        top = y_;
    };
    header();
    for (std::size_t k = from; k < to; ++k) {
        const auto& r = t.rows[k];
        const double h = rowHeight(t, k, x);
        if (y_ + h > area_.height() - line_ && y_ > top) {  // the header repeated on the next page
            rules();
            newPage();
            header();
        }
        Row row;
        for (std::size_t i = 0; i < r.size(); ++i) {
            const QRectF cell(x[i], y_, x[i + 1] - x[i], line_);
            cellText(row, inner(cell), r[i], t.numeric[i]);
        }
        for (const RowRun& run : row) {
            QGlyphRun glyphs;
            glyphs.setRawFont(run.font);
            glyphs.setGlyphIndexes(run.indexes);
            glyphs.setPositions(run.positions);
            p_.drawGlyphRun(QPointF(0, 0), glyphs);
        }
        y_ += h;
        p_.drawLine(QPointF(0, y_), QPointF(area_.width(), y_));
    }
    rules();
}

void PagePainter::cellText(Row& row, const QRectF& cell, const std::string& text, bool right)
{
    const Fitted& f = fit(cell.width(), text, !right);
    const double x = right ? cell.right() - f.advance : cell.left();
    const QPointF at(x, baseline(cell) - f.ascent);
    for (const QGlyphRun& run : f.glyphs) {
        const QRawFont font = run.rawFont();
        auto same = std::find_if(row.begin(), row.end(), [&](const RowRun& r) { return r.font == font; });
        if (same == row.end()) same = row.insert(row.end(), RowRun{font, {}, {}});
        same->indexes += run.glyphIndexes();
        for (const QPointF& p : run.positions()) same->positions.push_back(p + at);
    }
}

std::vector<double> PagePainter::columns(const sheet::Table& t) const
{
    const double total = std::accumulate(t.widths.begin(), t.widths.end(), 0.0);
    std::vector<double> x{0};
    for (const double w : t.widths) x.push_back(x.back() + w / total * area_.width());
    return x;
}

double PagePainter::rowHeight(const sheet::Table& t, std::size_t k, const std::vector<double>& x)
{
    double more = 0;
    for (std::size_t i = 0; i < t.rows[k].size(); ++i) {
        if (t.numeric[i]) continue;
        const Fitted& f = fit(inner(QRectF(x[i], 0, x[i + 1] - x[i], line_)).width(), t.rows[k][i], true);
        more = std::max(more, f.height - f.lineHeight);
    }
    return line_ + more;
}

void PagePainter::headerText(const QRectF& cell, const std::string& text)
{
    auto& laid = headers_[cell.width()];
    auto it = laid.find(text);
    if (it == laid.end()) {
        Fitted f;
        QTextLayout layout(q(text), bold_, &pdf_);
        QTextOption wrap;
        wrap.setWrapMode(QTextOption::WordWrap);  // as drawText with Qt::TextWordWrap
        layout.setTextOption(wrap);
        layout.beginLayout();
        double height = 0;
        for (QTextLine line = layout.createLine(); line.isValid(); line = layout.createLine()) {
            line.setLineWidth(cell.width());
            line.setPosition(QPointF(0, height));
            height += line.height();
        }
        layout.endLayout();
        f.glyphs = layout.glyphRuns();
        f.height = height;
        it = laid.emplace(text, std::move(f)).first;
    }
    const QPointF at(cell.left(), cell.center().y() - it->second.height / 2);
    for (const QGlyphRun& run : it->second.glyphs) p_.drawGlyphRun(at, run);
}

}  // namespace taiwa::sheetpdf
