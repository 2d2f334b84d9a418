// The core's words the operator reads in the station, in the station's
// language: the step kinds ("Roughing I") and the meanings of the codes
// U, F, H. The core keeps them in English (tapes, sheets, the command
// line); their translations are sources of context "taiwa::CoreTexts" here.
#pragma once

#include "model/step.h"

#include <QString>

#include <string>
#include <string_view>

namespace taiwa::ui {

// A step's label as the station shows it: its kind translated, its number
// in roman numerals ("荒加工 I").
QString stepLabel(const Step& step);
// A code's meaning ("roughing only", a probing unit's "round (boss or
// bore)", a profile's "outer (OD)") translated; as it is when the catalogue
// has no entry for it (-X, +Y).
QString codeMeaning(std::string_view meaning);
// A diagnostic's field key ("stock.height", "figure[3]") in the station's
// words, part by part; a part with no translation as it is (alpha1, S).
QString fieldText(const std::string& field);
// The 3-D view's scale note for axes of `mm` millimetres ("axes 50 mm", "軸 50 mm")
// and the font file it is written with (VTK's own fonts have no Japanese or
// Chinese): IPA Gothic or WenQuanYi Micro Hei (the package recommends both);
// English, with no font file, when neither is installed.
QString axesNote(int mm);
QString axesNoteFont();
// Every text of the core this file translates (a test checks each has a translation).
QStringList coreTextSources();

}  // namespace taiwa::ui
