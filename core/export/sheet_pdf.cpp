// The instruction sheet as a PDF, painted through Qt's own PDF writer
// (export/page_painter.h): A4 landscape, the table header repeated on every
// page, long text wrapped in its column. A large job's steps table is
// painted in two parts at once, by two PDF writers, and the parts joined
// (export/pdf_merge.h): Qt's writer puts each glyph in the page's text
// and compresses every page, so a 10,000-unit sheet (1,177 pages) took
// most of an export's time on one thread.
#include "export/sheet_pdf.h"

#include "export/page_painter.h"
#include "export/pdf_merge.h"
#include "io/job_io.h"
#include "model/translate_noop.h"

#include "sheet/sheet_content.h"

#include <QBuffer>
#include <QGuiApplication>
#include <QPageSize>

#include <future>
#include <memory>

namespace taiwa {

using sheetpdf::PagePainter;
using sheetpdf::q;

namespace {

// A steps table of at least this many rows (some 23 pages) is painted in
// two parts: below it, joining costs more than it saves.
constexpr std::size_t kRowsToSplit = 1000;

// One PDF writer painting into memory, from page `firstPage` on. The bytes
// are written like every other file, to the last byte and synced
// (QPdfWriter on a file reports no write error).
class Document {
public:
    Document(const sheet::Content& c, const Plan& plan, int firstPage) : pdf_(&bytes_)
    {
        bytes_.open(QIODevice::WriteOnly);
        pdf_.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Landscape, QMarginsF(12, 12, 12, 12),
                                       QPageLayout::Millimeter));
        pdf_.setResolution(300);
        pdf_.setTitle(q(c.title + " – " + plan.job.name));
        pdf_.setCreator(QStringLiteral("Taiwa " TAIWA_VERSION));
        if (painter_.begin(&pdf_)) {
            painter_.setPen(QPen(Qt::black, 1));
            page_ = std::make_unique<PagePainter>(pdf_, painter_, firstPage);
        }
    }
    PagePainter* page() { return page_.get(); }
    Result<std::string> finish()
    {
        if (!page_) return Failure{TAIWA_TRANSLATE_NOOP("taiwa::msg", "cannot paint the instruction sheet's PDF")};
        page_->finish();
        if (!painter_.end() || bytes_.data().isEmpty()) return Failure{TAIWA_TRANSLATE_NOOP("taiwa::msg", "cannot paint the instruction sheet's PDF")};
        return std::string(bytes_.data().constData(), static_cast<std::size_t>(bytes_.data().size()));
    }

private:
    QBuffer bytes_;
    QPdfWriter pdf_;
    QPainter painter_;
    std::unique_ptr<PagePainter> page_;
};

// What follows the steps table, to the end.
void afterSteps(PagePainter& page, const sheet::Content& c)
{
    for (const auto& p : c.paths) {
        page.heading(p.heading);
        page.table(p.table);
        if (!p.note.empty()) page.paragraph(p.note);
    }
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
}

}  // namespace

Result<std::string> sheetPdf(const Plan& plan, const SheetOptions& options, PdfParts parts)
{
    if (!QGuiApplication::instance()) return Failure{"the PDF writer needs a QGuiApplication"};
    const sheet::Content c = sheet::content(plan, options);
    Document first(c, plan, 1);
    PagePainter* page = first.page();
    if (!page) return first.finish();
    page->title(c.title);
    page->fields(c.fields);
    page->paragraph(c.setup);
    if (!c.clamping.empty()) page->paragraph(c.clamping);
    if (!c.toolsOrigin.empty()) page->paragraph(c.toolsOrigin);
    if (c.setupPicture) page->pictures({*c.setupPicture});
    if (!c.faults.empty()) {
        const QColor red(192, 0, 0);
        page->paragraph("Verification: written with faults (--force)", red);
        for (const auto& f : c.faults) page->paragraph("- " + f, red);
    }
    if (!c.allowances.rows.empty()) {
        page->heading("Grinding allowances");
        page->table(c.allowances);
        page->heading("Turned profile as cut");
        page->table(c.turned);
    }
    if (!c.workCentre.rows.empty()) {
        page->heading("Work centre");
        page->table(c.workCentre);
    }
    page->heading("Process steps");
    const bool split = parts == PdfParts::Two || (parts == PdfParts::BySize && c.steps.rows.size() >= kRowsToSplit);
    const auto cut = split ? page->cutNearMiddle(c.steps) : std::nullopt;
    if (!cut) {
        page->table(c.steps);
        afterSteps(*page, c);
        return first.finish();
    }
    // The second part, from the page the cut row starts, on a thread of its
    // own; this one paints the first up to it.
    auto second = std::async(std::launch::async, [&] {
        Document rest(c, plan, cut->page);
        if (!rest.page()) return rest.finish();
        rest.page()->table(c.steps, cut->row);
        afterSteps(*rest.page(), c);
        return rest.finish();
    });
    page->table(c.steps, 0, cut->row);
    auto one = first.finish();
    auto two = second.get();
    if (!one) return one;
    if (!two) return two;
    return joinPdfs({*one, *two});
}

Result<void> writeSheetPdf(const Plan& plan, const SheetOptions& options, const std::string& path)
{
    auto pdf = sheetPdf(plan, options, PdfParts::BySize);
    if (!pdf) return pdf.failure();
    return writeFileAtomically(path, *pdf);
}

}  // namespace taiwa
