// The instruction sheet as a PDF, painted through Qt's own PDF writer: A4
// landscape, the table header repeated on every page, long text elided to
// its column. Painting directly keeps a 1,000-unit job's sheet fast.
#include "export/sheet_pdf.h"

#include "io/job_io.h"
#include "model/translate_noop.h"

#include "sheet/sheet_content.h"

#include <QBuffer>
#include <QImage>
#include <QFile>
#include <QFontMetricsF>
#include <QGlyphRun>
#include <QGuiApplication>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QTextLayout>

#include <algorithm>
#include <functional>
#include <map>
#include <numeric>
#include <unordered_map>

namespace taiwa {

namespace {

QString q(const std::string& s) { return QString::fromStdString(s); }

class PagePainter {
public:
    PagePainter(QPdfWriter& pdf, QPainter& p) : pdf_(pdf), p_(p)
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

    void table(const sheet::Table& t)
    {
        const double total = std::accumulate(t.widths.begin(), t.widths.end(), 0.0);
        std::vector<double> x{0};
        for (const double w : t.widths) x.push_back(x.back() + w / total * area_.width());
        // The header takes two lines, so that "Depth mm" wraps instead of being elided.
        // A header is drawn cell by cell; a body row as one line under it and
        // one glyph run per font, and the columns' rules once per page from
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
        for (const auto& r : t.rows) {
            if (y_ + line_ > area_.height() - line_) {  // the header repeated on the next page
                rules();
                newPage();
                header();
            }
            Row row;
            for (std::size_t i = 0; i < r.size(); ++i) {
                const QRectF cell(x[i], y_, x[i + 1] - x[i], line_);
                cellText(row, cell.adjusted(line_ * 0.2, 0, -line_ * 0.2, 0), r[i], t.numeric[i]);
            }
            for (const RowRun& run : row) {
                QGlyphRun glyphs;
                glyphs.setRawFont(run.font);
                glyphs.setGlyphIndexes(run.indexes);
                glyphs.setPositions(run.positions);
                p_.drawGlyphRun(QPointF(0, 0), glyphs);
            }
            y_ += line_;
            p_.drawLine(QPointF(0, y_), QPointF(area_.width(), y_));
        }
        rules();
    }

    void paragraph(const std::string& text, const QColor& colour = Qt::black)
    {
        ensure(line_);
        const QPen pen = p_.pen();
        p_.setPen(colour);
        p_.drawText(QRectF(0, y_, area_.width(), line_), Qt::AlignLeft | Qt::AlignVCenter, elide(q(text), area_.width()));
        p_.setPen(pen);
        y_ += line_;
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
    // `captions.size()` cells `perRow` to a row, each `aspect` as high as
    // wide with its caption under it and a frame, drawn by `paint`; a row
    // that does not fit goes on the next page.
    void grid(const std::vector<std::string>& captions, int perRow, double aspect,
              const std::function<void(std::size_t, const QRectF&)>& paint)
    {
        const double gap = line_ * 0.5;
        const double w = (area_.width() - gap * (perRow - 1)) / perRow, h = w * aspect;
        for (std::size_t i = 0; i < captions.size(); ++i) {
            const int col = static_cast<int>(i % static_cast<std::size_t>(perRow));
            if (col == 0) {
                if (i > 0) y_ += h + line_ + gap;
                ensure(h + line_);
            }
            const QRectF box(col * (w + gap), y_, w, h);
            paint(i, box);
            p_.drawRect(box);
            p_.drawText(QRectF(box.left(), box.bottom(), w, line_), Qt::AlignLeft | Qt::AlignVCenter,
                        elide(q(captions[i]), w));
        }
        if (!captions.empty()) y_ += h + line_ + gap;
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
    // A body cell's text, elided to the cell and aligned right (numbers) or
    // left, on the cell's middle line, added to its row. Cells repeat
    // (modules, tools, labels, numbers): each text is elided, shaped and
    // measured once per column width (laying a text out in a rectangle,
    // then shaping it, were most of a 150-page sheet's time).
    void cellText(Row& row, const QRectF& cell, const std::string& text, bool right)
    {
        auto& fitted = fitted_[cell.width()];
        auto it = fitted.find(text);
        if (it == fitted.end()) {
            Fitted f;
            QTextLayout layout(normalMetrics_.elidedText(q(text), Qt::ElideRight, cell.width()), normal_, &pdf_);
            layout.beginLayout();
            QTextLine line = layout.createLine();
            layout.endLayout();
            f.glyphs = layout.glyphRuns();
            f.advance = line.isValid() ? line.naturalTextWidth() : 0.0;
            f.ascent = line.isValid() ? line.ascent() : 0.0;
            it = fitted.emplace(text, std::move(f)).first;
        }
        const Fitted& f = it->second;
        const double x = right ? cell.right() - f.advance : cell.left();
        const double baseline = cell.center().y() + (normalMetrics_.ascent() - normalMetrics_.descent()) / 2;
        const QPointF at(x, baseline - f.ascent);
        for (const QGlyphRun& run : f.glyphs) {
            const QRawFont font = run.rawFont();
            auto same = std::find_if(row.begin(), row.end(), [&](const RowRun& r) { return r.font == font; });
            if (same == row.end()) same = row.insert(row.end(), RowRun{font, {}, {}});
            same->indexes += run.glyphIndexes();
            for (const QPointF& p : run.positions()) same->positions.push_back(p + at);
        }
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
    struct Fitted {
        QList<QGlyphRun> glyphs;  // the text (body cells: elided), shaped
        double advance = 0, ascent = 0;  // body cells: one line
        double height = 0;               // header cells: every wrapped line
    };
    std::map<double, std::unordered_map<std::string, Fitted>> fitted_;   // by column width
    std::map<double, std::unordered_map<std::string, Fitted>> headers_;  // the same for header cells
    double line_ = 0, y_ = 0;
    int page_ = 1;
};

}  // namespace

Result<std::string> sheetPdf(const Plan& plan, const SheetOptions& options)
{
    if (!QGuiApplication::instance()) return Failure{"the PDF writer needs a QGuiApplication"};
    const sheet::Content c = sheet::content(plan, options);
    // Painted into memory: the bytes are written like every other file, to
    // the last byte and synced (QPdfWriter on a file reports no write error).
    QBuffer bytes;
    bytes.open(QIODevice::WriteOnly);
    QPdfWriter pdf(&bytes);
    pdf.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Landscape, QMarginsF(12, 12, 12, 12),
                                  QPageLayout::Millimeter));
    pdf.setResolution(300);
    pdf.setTitle(q(c.title + " – " + plan.job.name));
    pdf.setCreator(QStringLiteral("Taiwa " TAIWA_VERSION));
    QPainter painter;
    if (!painter.begin(&pdf)) return Failure{TAIWA_TRANSLATE_NOOP("taiwa::msg", "cannot paint the instruction sheet's PDF")};
    painter.setPen(QPen(Qt::black, 1));
    PagePainter page(pdf, painter);
    page.title(c.title);
    page.fields(c.fields);
    page.paragraph(c.setup);
    if (!c.clamping.empty()) page.paragraph(c.clamping);
    if (c.setupPicture) page.pictures({*c.setupPicture});
    if (!c.faults.empty()) {
        const QColor red(192, 0, 0);
        page.paragraph("Verification: written with faults (--force)", red);
        for (const auto& f : c.faults) page.paragraph("- " + f, red);
    }
    if (!c.allowances.rows.empty()) {
        page.heading("Grinding allowances");
        page.table(c.allowances);
        page.heading("Turned profile as cut");
        page.table(c.turned);
    }
    if (!c.workCentre.rows.empty()) {
        page.heading("Work centre");
        page.table(c.workCentre);
    }
    page.heading("Process steps");
    page.table(c.steps);
    if (!c.pictures.empty() || !c.picturesNote.empty()) {
        page.heading("The steps in pictures");
        if (!c.picturesNote.empty()) page.paragraph(c.picturesNote);
        page.pictures(c.pictures);
    }
    page.heading("Tools");
    page.table(c.tools);
    page.drawings(c.toolDrawings);
    if (!c.latheTools.rows.empty()) {
        page.heading("Turret");
        page.table(c.latheTools);
    }
    if (!c.notes.empty()) {
        page.heading("Notes");
        for (const auto& n : c.notes) page.paragraph("- " + n);
    }
    page.paragraph("Total: " + c.total + ".");
    page.finish();
    if (!painter.end() || bytes.data().isEmpty()) return Failure{TAIWA_TRANSLATE_NOOP("taiwa::msg", "cannot paint the instruction sheet's PDF")};
    return std::string(bytes.data().constData(), static_cast<std::size_t>(bytes.data().size()));
}

Result<void> writeSheetPdf(const Plan& plan, const SheetOptions& options, const std::string& path)
{
    auto pdf = sheetPdf(plan, options);
    if (!pdf) return Failure{pdf.error()};
    return writeFileAtomically(path, *pdf);
}

}  // namespace taiwa
