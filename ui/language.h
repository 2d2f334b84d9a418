// The station's language: English (the source texts), Japanese or
// Simplified Chinese (a QTranslator over resources/i18n/taiwa_ja.ts or
// taiwa_zh.ts, compiled into the program, and one over Qt's own texts,
// qtbase_ja / qtbase_zh_CN from Debian's qt6-translations-l10n, for the
// standard buttons and dialogs).
// The choice is kept in QSettings and applies at the next start; the
// environment variable TAIWA_LANG (en, ja, zh) overrides it for one run.
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
// Installs the translators of the language in force; false for English or
// when the translation is missing. Qt's own translation is installed when
// found (a missing one leaves the standard buttons in English, with a warning).
bool installTranslator(QCoreApplication& app);
// The language whose translator is installed ("ja", "zh"); empty for English.
QString installedLanguage();

}  // namespace taiwa::ui
