// The sheet's pictures for an export (sheet_pictures.h).
#include "export/sheet_pictures.h"

#include "picture/pictures.h"

#include <QBuffer>
#include <QFont>
#include <QGuiApplication>
#include <QImage>
#include <QPainter>

#include <stdexcept>

namespace taiwa {

std::string pngOf(const picture::Picture& p)
{
    const picture::Image& im = p.image;
    if (im.width <= 0 || im.height <= 0 || im.rgba.size() != 4 * static_cast<std::size_t>(im.width) * im.height) return {};
    QImage image(im.rgba.data(), im.width, im.height, 4 * im.width, QImage::Format_RGBA8888);
    image = image.convertToFormat(QImage::Format_RGB32);  // a copy of its own, opaque
    if (!p.labels.empty() && qobject_cast<QGuiApplication*>(QCoreApplication::instance())) {
        QPainter painter(&image);
        painter.setRenderHint(QPainter::TextAntialiasing);
        for (const picture::Label& l : p.labels) {
            QFont font(QStringLiteral("DejaVu Sans"));
            font.setPixelSize(l.pixelSize);
            font.setBold(l.bold);
            painter.setFont(font);
            painter.setPen(QColor(l.colour.r, l.colour.g, l.colour.b));
            const QString text = QString::fromStdString(l.text);
            const double width = l.right ? painter.fontMetrics().horizontalAdvance(text) : 0;
            painter.drawText(QPointF(l.x - width, l.y), text);
        }
    }
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    // Compression level 1 (Qt: quality 80): a third of the default's time, a few per cent larger.
    if (!image.save(&buffer, "PNG", 80)) return {};
    return bytes.toStdString();
}

std::string addSheetPictures(const Plan& plan, ExportOptions& options, int limit)
{
    using namespace picture;
    std::string problem;
    options.stepPictures.clear();
    options.setupPicture.clear();
    options.picturesNote.clear();
    try {
        options.setupPicture = pngOf(setupPicture(plan, kSheetWidth, kSheetHeight));
        if (options.setupPicture.empty()) problem = "the picture of the setup cannot be encoded";
    } catch (const std::exception& e) {
        problem = std::string("the picture of the setup cannot be drawn: ") + e.what();
    }
    if (plan.steps.empty()) return problem;
    auto pictures = stepPictures(plan, kSheetWidth, kSheetHeight, limit);
    if (!pictures) {
        options.picturesNote = "No pictures of the steps: " + pictures.error() + ".";
        return pictures.error();
    }
    for (std::size_t k = 0; k < pictures->size(); ++k) {
        std::string png = pngOf((*pictures)[k]);
        if (png.empty() && problem.empty()) problem = "the picture of step " + std::to_string(k + 1) + " cannot be encoded";
        options.stepPictures.push_back(std::move(png));
    }
    if (!problem.empty()) options.picturesNote = "Pictures missing: " + problem + ".";
    else if (plan.steps.size() > options.stepPictures.size())
        options.picturesNote = "Pictures of the first " + std::to_string(options.stepPictures.size()) + " of " +
                               std::to_string(plan.steps.size()) + " steps.";
    return problem;
}

}  // namespace taiwa
