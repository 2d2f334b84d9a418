// The core's words in the station's language (core_texts.h).
#include "ui/core_texts.h"

#include <QCoreApplication>

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

QStringList coreTextSources()
{
    QStringList out;
    for (const char* s : kSources) out << QString::fromUtf8(s);
    return out;
}

}  // namespace taiwa::ui
