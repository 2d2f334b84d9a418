// The instruction sheet as a PDF: the HTML laid out by QTextDocument and
// printed through Qt's own PDF writer, A4 landscape.
#include "sheet/sheet.h"

#include <QFile>
#include <QGuiApplication>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QTextDocument>

namespace taiwa {

std::optional<std::string> writeSheetPdf(const Plan& plan, const SheetOptions& options, const std::string& path)
{
    if (!QGuiApplication::instance()) return std::string("the PDF writer needs a QGuiApplication");
    QPdfWriter pdf(QString::fromStdString(path));
    pdf.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Landscape, QMarginsF(12, 12, 12, 12),
                                  QPageLayout::Millimeter));
    pdf.setResolution(300);
    pdf.setTitle(QString::fromStdString("Machining instruction sheet – " + plan.job.name));
    pdf.setCreator(QStringLiteral("Taiwa " TAIWA_VERSION));
    QTextDocument doc;
    doc.setHtml(QString::fromStdString(sheetHtml(plan, options)));
    QFont font(QStringLiteral("DejaVu Sans"));
    font.setPointSizeF(9);
    doc.setDefaultFont(font);
    doc.print(&pdf);
    QFile f(QString::fromStdString(path));
    if (!f.exists() || f.size() == 0) return "cannot write " + path;
    return std::nullopt;
}

}  // namespace taiwa
