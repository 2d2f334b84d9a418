// The station's language in GUI tests: the translators of a language put in
// place of those installed before, as the station installs them at start.
#pragma once

#include "ui/language.h"

#include <QCoreApplication>
#include <QTranslator>

namespace taiwa::test {

// The station's translators for `language` ("en": none).
inline void speak(const char* language)
{
    for (auto* t : QCoreApplication::instance()->findChildren<QTranslator*>()) {
        QCoreApplication::removeTranslator(t);
        delete t;
    }
    qputenv("TAIWA_LANG", language);
    ui::installTranslator(*QCoreApplication::instance());
}

}  // namespace taiwa::test
