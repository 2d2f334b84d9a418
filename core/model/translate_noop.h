// Marks a source text of the station's translation in the core, which has
// no Qt: the macro is the text itself, and lupdate (run by
// resources/i18n/update-ts.py with -tr-function-alias
// QT_TRANSLATE_NOOP+=TAIWA_TRANSLATE_NOOP) collects it under its context.
// The core's messages are marked in context "taiwa::msg": each is a fmt
// template whose English rendering the core writes, and which the station
// translates (ui/core_messages.h). docs/station.md, "Languages", explains.
#pragma once

#define TAIWA_TRANSLATE_NOOP(context, text) text
