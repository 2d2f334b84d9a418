// The station's language: English (the source texts) or Japanese (a
// QTranslator over resources/i18n/taiwa_ja.ts, compiled into the program).
// The choice is kept in QSettings and applies at the next start; the
// environment variable TAIWA_LANG (en, ja) overrides it for one run.
#pragma once

#include <QString>

#include <utility>
#include <vector>

class QCoreApplication;

namespace taiwa::ui {

// Language codes with their names as shown in the menu.
std::vector<std::pair<QString, QString>> availableLanguages();
QString savedLanguage();
void saveLanguage(const QString& code);
// Installs the translator of the language in force; false for English or
// when the translation is missing.
bool installTranslator(QCoreApplication& app);

}  // namespace taiwa::ui
