// The instruction sheet's pages painted on a QPdfWriter (export/sheet_pdf.cpp):
// title, fields, paragraphs, tables with their header repeated on every
// page and long text wrapped in its column (a unit's or a tool's name is
// never cut: the row grows), pictures and tool drawings, the
// page number at the foot. A table can be drawn in parts by two painters
// (two PDF writers at once), each part starting where the other would
// have turned the page.
#pragma once

#include "sheet/sheet_content.h"

#include <QFontMetricsF>
#include <QGlyphRun>
#include <QImage>
#include <QPageLayout>
#include <QPainter>
#include <QPdfWriter>
#include <QTextLayout>

#include <algorithm>
#include <functional>
#include <map>
#include <numeric>
#include <optional>
#include <unordered_map>

namespace taiwa::sheetpdf {

inline QString q(const std::string& s) { return QString::fromStdString(s); }

class PagePainter {
public:
    // `firstPage`: the number of the first page this painter paints.
    PagePainter(QPdfWriter& pdf, QPainter& p, int firstPage = 1) : pdf_(pdf), p_(p), page_(firstPage)
    {
        area_ = QRectF(QPointF(0, 0), pdf.pageLayout().paintRectPixels(pdf.resolution()).size());
        normal_ = QFont(QStringLiteral("DejaVu Sans"));
        normal_.setPointSizeF(9);
        bold_ = normal_;
        bold_.setBold(true);
        title_ = bold_;
        title_.setPointSizeF(14);
        p_.setFont(normal_);
        line_ = QFontMetricsF(normal_, &pdf_).height() * 1.35;
        normalMetrics_ = QFontMetricsF(normal_, &pdf_);
    }

    void title(const std::string& text)
    {
        p_.setFont(title_);
        const double h = QFontMetricsF(title_, &pdf_).height();
        p_.drawText(QRectF(0, y_, area_.width(), h), Qt::AlignLeft | Qt::AlignVCenter, q(text));
        y_ += h * 1.3;
        p_.setFont(normal_);
    }

    void heading(const std::string& text)
    {
        ensure(4.5 * line_);  // the heading, a table header and one row stay together
        y_ += line_ * 0.4;
        p_.setFont(bold_);
        p_.drawText(QRectF(0, y_, area_.width(), line_), Qt::AlignLeft | Qt::AlignVCenter, q(text));
        p_.setFont(normal_);
        y_ += line_;
    }

    void fields(const std::vector<std::pair<std::string, std::string>>& f)
    {
        const double col = area_.width() / 3;
        for (std::size_t i = 0; i < f.size(); ++i) {
            const double x = static_cast<double>(i % 3) * col;
            p_.setFont(bold_);
            p_.drawText(QRectF(x, y_, col * 0.28, line_), Qt::AlignLeft | Qt::AlignVCenter, q(f[i].first));
            p_.setFont(normal_);
            const QRectF value(x + col * 0.28, y_, col * 0.7, line_);
            p_.drawText(value, Qt::AlignLeft | Qt::AlignVCenter, elide(q(f[i].second), value.width()));
            if (i % 3 == 2 || i + 1 == f.size()) y_ += line_;
        }
    }

    // Where a table of `rows` rows, its header drawn from here on, can be
    // cut for a second painter: at a page break near its middle. The
    // second part's first row and the number of its first page; none for a
    // table that ends on the page it starts on.
    struct Cut {
        std::size_t row = 0;
        int page = 0;
    };
    std::optional<Cut> cutNearMiddle(const sheet::Table& t)
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

    // The table's rows [from, to); a part that starts past the first row
    // starts on a fresh page, as the whole table would turn to it there.
    void table(const sheet::Table& t, std::size_t from = 0, std::size_t to = static_cast<std::size_t>(-1))
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

    // A paragraph wrapped at the page's width.
    void paragraph(const std::string& text, const QColor& colour = Qt::black)
    {
        const Fitted& f = fit(area_.width(), text, true);
        const double h = line_ + f.height - f.lineHeight;
        ensure(h);
        const QPen pen = p_.pen();
        p_.setPen(colour);
        drawFitted(f, QRectF(0, y_, area_.width(), line_));
        p_.setPen(pen);
        y_ += h;
    }

    // Pictures four to a row, each with its caption under it.
    void pictures(const std::vector<sheet::Content::Picture>& pics)
    {
        std::vector<std::string> captions;
        for (const auto& p : pics) captions.push_back(p.caption);
        grid(captions, 4, 0.75, [&](std::size_t i, const QRectF& box) {
            const QImage image = QImage::fromData(reinterpret_cast<const uchar*>(pics[i].png.data()),
                                                  static_cast<int>(pics[i].png.size()), "PNG");
            if (!image.isNull()) p_.drawImage(box, image);
        });
    }

    // The tools' drawings six to a row, each painted from the shapes the
    // HTML's SVG is written from.
    void drawings(const std::vector<sheet::Content::Drawing>& ds)
    {
        std::vector<std::string> captions;
        for (const auto& d : ds) captions.push_back(d.caption);
        grid(captions, 6, sheet::ToolDrawing::kHeight / sheet::ToolDrawing::kWidth,
             [&](std::size_t i, const QRectF& box) { drawing(ds[i].drawing, box); });
    }

    void finish() { footer(); }

private:
    // A text laid out and shaped, ready to be drawn from its glyphs.
    struct Fitted {
        QList<QGlyphRun> glyphs;  // the text (numbers: elided), shaped
        double advance = 0, ascent = 0, lineHeight = 0;  // its first line
        double height = 0;                               // every line
    };

    // `captions.size()` cells `perRow` to a row, each `aspect` as high as
    // wide with its caption under it and a frame, drawn by `paint`; a row
    // that does not fit goes on the next page.
    void grid(const std::vector<std::string>& captions, int perRow, double aspect,
              const std::function<void(std::size_t, const QRectF&)>& paint)
    {
        const double gap = line_ * 0.5;
        const double w = (area_.width() - gap * (perRow - 1)) / perRow, h = w * aspect;
        const std::size_t n = static_cast<std::size_t>(perRow);
        double under = line_;  // the row's captions, wrapped: as high as its longest
        for (std::size_t i = 0; i < captions.size(); ++i) {
            const int col = static_cast<int>(i % n);
            if (col == 0) {
                if (i > 0) y_ += h + under + gap;
                under = line_;
                for (std::size_t k = i; k < std::min(captions.size(), i + n); ++k) {
                    const Fitted& f = fit(w, captions[k], true);
                    under = std::max(under, line_ + f.height - f.lineHeight);
                }
                ensure(h + under);
            }
            const QRectF box(col * (w + gap), y_, w, h);
            paint(i, box);
            p_.drawRect(box);
            drawFitted(fit(w, captions[i], true), QRectF(box.left(), box.bottom(), w, line_));
        }
        if (!captions.empty()) y_ += h + under + gap;
    }

    // A tool's drawing scaled from its canvas into `box`.
    void drawing(const sheet::ToolDrawing& d, const QRectF& box)
    {
        const double k = box.width() / sheet::ToolDrawing::kWidth;
        const auto at = [&](const Point2& p) { return QPointF(box.left() + p.x * k, box.top() + p.y * k); };
        p_.save();
        p_.setRenderHint(QPainter::Antialiasing);
        for (const auto& shape : d.shapes) {
            QPolygonF polygon;
            for (const auto& p : shape.points) polygon << at(p);
            p_.setPen(shape.part == sheet::ToolDrawing::Part::Arrow ? QPen(Qt::NoPen) : QPen(Qt::black, 0.6 * k));
            p_.setBrush(QColor(q(shape.fill)));
            p_.drawPolygon(polygon);
        }
        for (const auto& l : d.lines) {
            QPen pen(Qt::black, 0.5 * k);
            if (l.dashed) pen.setDashPattern({12, 4, 2, 4});  // the SVG's "6 2 1 2", in pen widths
            p_.setPen(pen);
            p_.drawLine(at(l.from), at(l.to));
        }
        QFont font = normal_;
        font.setPointSizeF(sheet::ToolDrawing::kTextSize * k * 72.0 / pdf_.resolution());
        p_.setFont(font);
        p_.setPen(Qt::black);
        const QFontMetricsF metrics(font, &pdf_);
        for (const auto& t : d.texts) p_.drawText(at(t.at) - QPointF(metrics.horizontalAdvance(q(t.text)) / 2, 0), q(t.text));
        p_.restore();
    }

    // A row's glyphs, gathered by font: indexes and positions on the page,
    // drawn as one run per font (one PDF text object a row, not one a cell).
    struct RowRun {
        QRawFont font;
        QList<quint32> indexes;
        QList<QPointF> positions;
    };
    using Row = std::vector<RowRun>;
    // A body cell's text, a number elided to the cell and aligned right, a
    // text wrapped in it (words kept whole where they fit: a unit's or a
    // tool's name is read whole, the row growing to it), its first line on
    // the cell's middle line, added to its row. Cells repeat (modules,
    // tools, labels, numbers): each text is laid out, shaped and measured
    // once per column width (laying a text out in a rectangle, then shaping
    // it, were most of a 150-page sheet's time).
    void cellText(Row& row, const QRectF& cell, const std::string& text, bool right)
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
    // A text in the normal font laid out once per width: on one line,
    // elided (`wrap` false), or wrapped at word boundaries, within a word
    // only where the word alone is wider than `width`.
    const Fitted& fit(double width, const std::string& text, bool wrap)
    {
        auto& fitted = fitted_[{width, wrap}];
        auto it = fitted.find(text);
        if (it != fitted.end()) return it->second;
        Fitted f;
        QTextLayout layout(wrap ? q(text) : normalMetrics_.elidedText(q(text), Qt::ElideRight, width), normal_, &pdf_);
        QTextOption option;
        option.setWrapMode(wrap ? QTextOption::WrapAtWordBoundaryOrAnywhere : QTextOption::NoWrap);
        layout.setTextOption(option);
        layout.beginLayout();
        double y = 0;
        for (QTextLine line = layout.createLine(); line.isValid(); line = layout.createLine()) {
            if (wrap) line.setLineWidth(width);  // laid out now; one line unwrapped is laid out by endLayout
            line.setPosition(QPointF(0, y));
            y += line.height();
        }
        layout.endLayout();
        for (int i = 0; i < layout.lineCount(); ++i) f.height += layout.lineAt(i).height();
        if (layout.lineCount() > 0) {
            const QTextLine first = layout.lineAt(0);
            f.advance = first.naturalTextWidth();
            f.ascent = first.ascent();
            f.lineHeight = first.height();
        }
        f.glyphs = layout.glyphRuns();
        return fitted.emplace(text, std::move(f)).first->second;
    }
    // A laid-out text drawn with its first line on the middle line of `first`.
    void drawFitted(const Fitted& f, const QRectF& first)
    {
        const QPointF at(first.left(), baseline(first) - f.ascent);
        for (const QGlyphRun& run : f.glyphs) p_.drawGlyphRun(at, run);
    }
    double baseline(const QRectF& cell) const
    {
        return cell.center().y() + (normalMetrics_.ascent() - normalMetrics_.descent()) / 2;
    }
    QRectF inner(const QRectF& cell) const { return cell.adjusted(line_ * 0.2, 0, -line_ * 0.2, 0); }
    // The columns' left edges and the table's right one.
    std::vector<double> columns(const sheet::Table& t) const
    {
        const double total = std::accumulate(t.widths.begin(), t.widths.end(), 0.0);
        std::vector<double> x{0};
        for (const double w : t.widths) x.push_back(x.back() + w / total * area_.width());
        return x;
    }
    // A body row's height: one line, and the further lines of its longest wrapped cell.
    double rowHeight(const sheet::Table& t, std::size_t k, const std::vector<double>& x)
    {
        double more = 0;
        for (std::size_t i = 0; i < t.rows[k].size(); ++i) {
            if (t.numeric[i]) continue;
            const Fitted& f = fit(inner(QRectF(x[i], 0, x[i + 1] - x[i], line_)).width(), t.rows[k][i], true);
            more = std::max(more, f.height - f.lineHeight);
        }
        return line_ + more;
    }
    // A header cell's text, wrapped in the cell and centred on its height,
    // in bold: laid out once per text and column width, drawn from its
    // glyphs on every page the table reaches.
    void headerText(const QRectF& cell, const std::string& text)
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
    QString elide(const QString& s, double width) const
    {
        return QFontMetricsF(p_.font(), &pdf_).elidedText(s, Qt::ElideRight, width);
    }
    void ensure(double h)
    {
        if (y_ + h > area_.height() - line_) newPage();
    }
    void footer()
    {
        p_.drawText(QRectF(0, area_.height() - line_, area_.width(), line_), Qt::AlignRight | Qt::AlignVCenter,
                    QStringLiteral("page %1").arg(page_));
    }
    void newPage()
    {
        footer();
        pdf_.newPage();
        ++page_;
        y_ = 0;
    }

    QPdfWriter& pdf_;
    QPainter& p_;
    QRectF area_;
    QFont normal_, bold_, title_;
    QFontMetricsF normalMetrics_{QFont()};
    std::map<std::pair<double, bool>, std::unordered_map<std::string, Fitted>> fitted_;  // by column width, wrapped or not
    std::map<double, std::unordered_map<std::string, Fitted>> headers_;  // the same for header cells
    double line_ = 0, y_ = 0;
    int page_ = 1;
};


}  // namespace taiwa::sheetpdf
