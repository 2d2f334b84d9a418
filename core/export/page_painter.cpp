// The sheet's page painter (page_painter.h): its fonts and page, the title,
// headings, fields, paragraphs, the grids of pictures and tool drawings,
// texts laid out and shaped once per width, and the page number at each
// page's foot. Its tables: page_painter_table.cpp.
#include "export/page_painter.h"

#include <QImage>
#include <QPageLayout>
#include <QTextLayout>

#include <algorithm>

namespace taiwa::sheetpdf {

// `firstPage`: the number of the first page this painter paints.
PagePainter::PagePainter(QPdfWriter& pdf, QPainter& p, int firstPage) : pdf_(pdf), p_(p), page_(firstPage)
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

void PagePainter::title(const std::string& text)
{
    p_.setFont(title_);
    const double h = QFontMetricsF(title_, &pdf_).height();
    p_.drawText(QRectF(0, y_, area_.width(), h), Qt::AlignLeft | Qt::AlignVCenter, q(text));
    y_ += h * 1.3;
    p_.setFont(normal_);
}

void PagePainter::heading(const std::string& text)
{
    ensure(4.5 * line_);  // the heading, a table header and one row stay together
    y_ += line_ * 0.4;
    p_.setFont(bold_);
    p_.drawText(QRectF(0, y_, area_.width(), line_), Qt::AlignLeft | Qt::AlignVCenter, q(text));
    p_.setFont(normal_);
    y_ += line_;
}

void PagePainter::fields(const std::vector<std::pair<std::string, std::string>>& f)
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

void PagePainter::paragraph(const std::string& text, const QColor& colour)
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

void PagePainter::pictures(const std::vector<sheet::Content::Picture>& pics)
{
    std::vector<std::string> captions;
    for (const auto& p : pics) captions.push_back(p.caption);
    grid(captions, 4, 0.75, [&](std::size_t i, const QRectF& box) {
        const QImage image = QImage::fromData(reinterpret_cast<const uchar*>(pics[i].png.data()),
                                              static_cast<int>(pics[i].png.size()), "PNG");
        if (!image.isNull()) p_.drawImage(box, image);
    });
}

void PagePainter::drawings(const std::vector<sheet::Content::Drawing>& ds)
{
    std::vector<std::string> captions;
    for (const auto& d : ds) captions.push_back(d.caption);
    grid(captions, 6, sheet::ToolDrawing::kHeight / sheet::ToolDrawing::kWidth,
         [&](std::size_t i, const QRectF& box) { drawing(ds[i].drawing, box); });
}

void PagePainter::grid(const std::vector<std::string>& captions, int perRow, double aspect,
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

void PagePainter::drawing(const sheet::ToolDrawing& d, const QRectF& box)
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

const PagePainter::Fitted& PagePainter::fit(double width, const std::string& text, bool wrap)
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

void PagePainter::drawFitted(const Fitted& f, const QRectF& first)
{
    const QPointF at(first.left(), baseline(first) - f.ascent);
    for (const QGlyphRun& run : f.glyphs) p_.drawGlyphRun(at, run);
}

void PagePainter::newPage()
{
    footer();
    pdf_.newPage();
    ++page_;
    y_ = 0;
}

}  // namespace taiwa::sheetpdf
