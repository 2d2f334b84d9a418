// The core's words in the station's language (core_texts.h).
#include "ui/core_texts.h"

#include "ui/language.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QRegularExpression>

#include <algorithm>
#include <array>

namespace taiwa::ui {

namespace {

constexpr const char* kContext = "taiwa::CoreTexts";

// The sources, as the core writes them (model/step.cpp toString with its
// first letter up, model/codes.cpp meaning()).
constexpr std::array kSources{
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "Pilot hole"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "Roughing"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "Floor finishing"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "Wall finishing"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "Inclined-face finishing"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "Facing"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "Centre drilling"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "Drilling"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "Grooving"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "Finishing"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "Threading"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "Parting off"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "Tapping"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "Reaming"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "Boring"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "roughing, floor finishing and wall finishing"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "roughing and floor finishing, walls left as roughed"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "floor and wall finishing of a pocket already cored"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "wall finishing only"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "roughing only"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "walls finished to full depth in one incision"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "walls finished in several Z incisions down to the floor"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "walls semi-finished leaving alpha3, then finished"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "drill a pilot hole first"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "no pilot hole, the roughing tool ramps in"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "round (boss or bore)"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "rectangular (block or pocket)"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "outside (boss, block)"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "inside (bore, pocket)"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "(round: none)"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "outer (OD)"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "inner (ID, a bore)"),
    // Face milling, side milling, area clearing (their steps and the codes of their forms).
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "Face milling"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "Side milling"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "Area clearing"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "roughing layers and a finishing pass"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "roughing only, the finishing pass left"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "one way, every pass climb"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "zigzag, back and forth"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "left of the contour"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "right of the contour"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "climb"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "conventional"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "roughing and finishing"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "finishing only"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "full depth at once"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "several incisions"),
    // The hole pattern's patterns and kinds of hole (modules/holes/holes_kind.cpp).
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "single"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "line"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "grid"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "bolt circle"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "arc"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "drilled"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "tapped"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "reamed"),
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "bored"),
    // The plan runner's note when the tool library is empty (ui/plan_runner.cpp).
    QT_TRANSLATE_NOOP("taiwa::CoreTexts", "the library has no tools"),
};

// The words of a diagnostic's field key ("stock.height", "figure[3]"), as
// the job file spells them (core/job/job_file_read.cpp, job/job_check.cpp).
constexpr const char* kFieldContext = "taiwa::Field";
[[maybe_unused]] constexpr std::array kFieldWords{
    QT_TRANSLATE_NOOP("taiwa::Field", "figure"),     QT_TRANSLATE_NOOP("taiwa::Field", "workOffset"),
    QT_TRANSLATE_NOOP("taiwa::Field", "stock"),      QT_TRANSLATE_NOOP("taiwa::Field", "clamping"),
    QT_TRANSLATE_NOOP("taiwa::Field", "technology"), QT_TRANSLATE_NOOP("taiwa::Field", "name"),
    QT_TRANSLATE_NOOP("taiwa::Field", "material"),   QT_TRANSLATE_NOOP("taiwa::Field", "machine"),
    QT_TRANSLATE_NOOP("taiwa::Field", "dialect"),    QT_TRANSLATE_NOOP("taiwa::Field", "lengthUnit"),
    QT_TRANSLATE_NOOP("taiwa::Field", "format"),     QT_TRANSLATE_NOOP("taiwa::Field", "version"),
    QT_TRANSLATE_NOOP("taiwa::Field", "units"),      QT_TRANSLATE_NOOP("taiwa::Field", "latheRoughing"),
    QT_TRANSLATE_NOOP("taiwa::Field", "height"),     QT_TRANSLATE_NOOP("taiwa::Field", "width"),
    QT_TRANSLATE_NOOP("taiwa::Field", "length"),     QT_TRANSLATE_NOOP("taiwa::Field", "diameter"),
    QT_TRANSLATE_NOOP("taiwa::Field", "face"),       QT_TRANSLATE_NOOP("taiwa::Field", "bore"),
    QT_TRANSLATE_NOOP("taiwa::Field", "shape"),      QT_TRANSLATE_NOOP("taiwa::Field", "fixture"),
    QT_TRANSLATE_NOOP("taiwa::Field", "grip"),       QT_TRANSLATE_NOOP("taiwa::Field", "touches"),
    QT_TRANSLATE_NOOP("taiwa::Field", "cutting"),    QT_TRANSLATE_NOOP("taiwa::Field", "module"),
    QT_TRANSLATE_NOOP("taiwa::Field", "unit"),
};

QString translated(const std::string& text) { return QCoreApplication::translate(kContext, text.c_str()); }

}  // namespace

QString stepLabel(const Step& step)
{
    // The label is the kind's name with its first letter up, then " I", " II"...
    std::string kind = toString(step.kind);
    if (!kind.empty()) kind[0] = static_cast<char>(kind[0] - 'a' + 'A');
    const std::string label = step.label();
    return translated(kind) + QString::fromStdString(label.substr(std::min(kind.size(), label.size())));
}

QString codeMeaning(std::string_view meaning) { return translated(std::string(meaning)); }

QString fieldText(const std::string& field)
{
    // Each part of "stock.height" or "figure[3]" translated, its index and the dots kept.
    static const QRegularExpression part(QStringLiteral("[A-Za-z]+"));
    const QString key = QString::fromStdString(field);
    QString out;
    qsizetype at = 0;
    for (auto it = part.globalMatch(key); it.hasNext();) {
        const auto m = it.next();
        out += key.mid(at, m.capturedStart() - at) +
               QCoreApplication::translate(kFieldContext, m.captured().toUtf8().constData());
        at = m.capturedEnd();
    }
    return out + key.mid(at);
}

QString axesNoteFont()
{
    const QString note = QCoreApplication::translate("taiwa::CoreTexts", "axes %1 mm");
    if (std::all_of(note.begin(), note.end(), [](QChar c) { return c.unicode() < 0x80; })) return {};
    const QStringList japanese{"/usr/share/fonts/opentype/ipafont-gothic/ipag.ttf",
                               "/usr/share/fonts/truetype/fonts-japanese-gothic.ttf"};
    QStringList files = installedLanguage() == "ja" ? japanese : QStringList();
    files << "/usr/share/fonts/truetype/wqy/wqy-microhei.ttc" << "/usr/share/fonts/truetype/wqy/wqy-zenhei.ttc";
    for (const QString& f : files)
        if (QFileInfo::exists(f)) return f;
    return {};
}

QString axesNote(int mm)
{
    if (axesNoteFont().isEmpty()) return QStringLiteral("axes %1 mm").arg(mm);  // no font to write it with
    return QCoreApplication::translate("taiwa::CoreTexts", "axes %1 mm").arg(mm);
}

QStringList coreTextSources()
{
    QStringList out;
    for (const char* s : kSources) out << QString::fromUtf8(s);
    return out;
}

}  // namespace taiwa::ui
