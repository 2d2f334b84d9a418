// Language choice and the translators (Japanese, Simplified Chinese).
#include "ui/language.h"

#include <QCoreApplication>
#include <QSettings>
#include <QTranslator>

namespace taiwa::ui {

std::vector<std::pair<QString, QString>> availableLanguages()
{
    return {{QStringLiteral("en"), QStringLiteral("English")},
            {QStringLiteral("ja"), QStringLiteral("日本語")},
            {QStringLiteral("zh"), QStringLiteral("中文(简体)")}};
}

QString savedLanguage()
{
    const QString env = qEnvironmentVariable("TAIWA_LANG");
    if (!env.isEmpty()) return env;
    return QSettings().value("language", "en").toString();
}

void saveLanguage(const QString& code) { QSettings().setValue("language", code); }

bool installTranslator(QCoreApplication& app)
{
    const QString code = savedLanguage();
    if (code == "en") return false;
    auto* translator = new QTranslator(&app);
    if (!translator->load(QStringLiteral(":/i18n/taiwa_%1.qm").arg(code))) {
        delete translator;
        qWarning("taiwa: no translation for language '%s'", qPrintable(code));
        return false;
    }
    return QCoreApplication::installTranslator(translator);
}

}  // namespace taiwa::ui
