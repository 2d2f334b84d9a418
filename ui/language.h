// The station's language: English (the source texts), Japanese or
// Simplified Chinese (a QTranslator over resources/i18n/taiwa_ja.ts or
// taiwa_zh.ts, compiled into the program, and one over Qt's own texts,
// qtbase_ja / qtbase_zh_CN from Debian's qt6-translations-l10n, for the
// standard buttons and dialogs).
// The choice is kept in QSettings; the environment variable TAIWA_LANG
// (en, ja, zh) overrides it for one run. switchLanguage changes it in the
// running station: every widget gets a LanguageChange and retranslates
// its menus, forms, tables and panels (docs/station.md, Language).
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
// Installs the translators of the language in force; false for English
// (whose catalogue holds its plural forms only: "1 block", "2 blocks") or
// when the translation is missing. Qt's own translation is installed when
// found (a missing one leaves the standard buttons in English, with a warning).
bool installTranslator(QCoreApplication& app);
// Saves `code` and puts its translators in place of the ones installed
// (TAIWA_LANG, which overrides the saved choice, is set to it for this
// run); the widgets are told by Qt (QEvent::LanguageChange). False when
// the translation is missing (English is then in force).
bool switchLanguage(const QString& code);
// The language whose translator is installed ("ja", "zh"); empty for English.
QString installedLanguage();

}  // namespace taiwa::ui
