// The instruction sheet's pages painted on a QPdfWriter (export/sheet_pdf.cpp):
// title, fields, paragraphs, tables with their header repeated on every
// page and long text wrapped in its column (a unit's or a tool's name is
// never cut: the row grows), pictures and tool drawings, the
// page number at the foot. A table can be drawn in parts by two painters
// (two PDF writers at once), each part starting where the other would
// have turned the page. The painting is in page_painter.cpp, the tables in
// page_painter_table.cpp.
#pragma once

#include "sheet/sheet_content.h"

#include <QFontMetricsF>
#include <QGlyphRun>
#include <QPainter>
#include <QPdfWriter>
#include <QRawFont>

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace taiwa::sheetpdf {

inline QString q(const std::string& s) { return QString::fromStdString(s); }

class PagePainter {
public:
    // `firstPage`: the number of the first page this painter paints.
    PagePainter(QPdfWriter& pdf, QPainter& p, int firstPage = 1);

    void title(const std::string& text);

    void heading(const std::string& text);

    void fields(const std::vector<std::pair<std::string, std::string>>& f);

    // Where a table of `rows` rows, its header drawn from here on, can be
    // cut for a second painter: at a page break near its middle. The
    // second part's first row and the number of its first page; none for a
    // table that ends on the page it starts on.
    struct Cut {
        std::size_t row = 0;
        int page = 0;
    };
    std::optional<Cut> cutNearMiddle(const sheet::Table& t);

    // The table's rows [from, to); a part that starts past the first row
    // starts on a fresh page, as the whole table would turn to it there.
    void table(const sheet::Table& t, std::size_t from = 0, std::size_t to = static_cast<std::size_t>(-1));

    // A paragraph wrapped at the page's width.
    void paragraph(const std::string& text, const QColor& colour = Qt::black);

    // Pictures four to a row, each with its caption under it.
    void pictures(const std::vector<sheet::Content::Picture>& pics);

    // The tools' drawings six to a row, each painted from the shapes the
    // HTML's SVG is written from.
    void drawings(const std::vector<sheet::Content::Drawing>& ds);

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
              const std::function<void(std::size_t, const QRectF&)>& paint);

    // A tool's drawing scaled from its canvas into `box`.
    void drawing(const sheet::ToolDrawing& d, const QRectF& box);

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
    void cellText(Row& row, const QRectF& cell, const std::string& text, bool right);
    // A text in the normal font laid out once per width: on one line,
    // elided (`wrap` false), or wrapped at word boundaries, within a word
    // only where the word alone is wider than `width`.
    const Fitted& fit(double width, const std::string& text, bool wrap);
    // A laid-out text drawn with its first line on the middle line of `first`.
    void drawFitted(const Fitted& f, const QRectF& first);
    double baseline(const QRectF& cell) const
    {
        return cell.center().y() + (normalMetrics_.ascent() - normalMetrics_.descent()) / 2;
    }
    QRectF inner(const QRectF& cell) const { return cell.adjusted(line_ * 0.2, 0, -line_ * 0.2, 0); }
    // The columns' left edges and the table's right one.
    std::vector<double> columns(const sheet::Table& t) const;
    // A body row's height: one line, and the further lines of its longest wrapped cell.
    double rowHeight(const sheet::Table& t, std::size_t k, const std::vector<double>& x);
    // A header cell's text, wrapped in the cell and centred on its height,
    // in bold: laid out once per text and column width, drawn from its
    // glyphs on every page the table reaches.
    void headerText(const QRectF& cell, const std::string& text);
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
    void newPage();

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
