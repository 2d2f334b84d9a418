// Language choice and the translators (Japanese, Simplified Chinese).
#include "ui/language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QPointer>
#include <QSettings>
#include <QTranslator>

#include <utility>

namespace taiwa::ui {

namespace {
QString& installed()
{
    static QString code;
    return code;
}
// The translators installTranslator put in, to be taken out on a switch.
// (Guarded: a test may have deleted them itself, tests/support/speak.h.)
QList<QPointer<QTranslator>>& ours()
{
    static QList<QPointer<QTranslator>> list;
    return list;
}
} // namespace

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
    installed().clear();
    const QString code = savedLanguage();
    if (code == "en") {
        // English is the source: only its plural forms ("1 block", "2 blocks").
        auto* plurals = new QTranslator(&app);
        if (plurals->load(QStringLiteral(":/i18n/taiwa_en.qm")) && QCoreApplication::installTranslator(plurals)) ours() << plurals;
        else delete plurals;
        return false;
    }
    auto* translator = new QTranslator(&app);
    if (!translator->load(QStringLiteral(":/i18n/taiwa_%1.qm").arg(code))) {
        delete translator;
        qWarning("taiwa: no translation for language '%s'", qPrintable(code));
        return false;
    }
    if (!QCoreApplication::installTranslator(translator)) {
        delete translator;
        return false;
    }
    ours() << translator;
    installed() = code;
    // Qt's own texts (QDialogButtonBox's OK, Cancel, Save; the file dialogs).
    auto* qt = new QTranslator(&app);
    const QString qtName = QStringLiteral("qtbase_%1").arg(code == "zh" ? QStringLiteral("zh_CN") : code);
    if (qt->load(qtName, QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        QCoreApplication::installTranslator(qt);
        ours() << qt;
    } else {
        delete qt;
        qWarning("taiwa: no Qt translation %s in %s (package qt6-translations-l10n)", qPrintable(qtName),
                 qPrintable(QLibraryInfo::path(QLibraryInfo::TranslationsPath)));
    }
    return true;
}

bool switchLanguage(const QString& code)
{
    saveLanguage(code);
    if (!qEnvironmentVariableIsEmpty("TAIWA_LANG")) qputenv("TAIWA_LANG", code.toUtf8());
    for (const QPointer<QTranslator>& t : std::exchange(ours(), {}))
        if (t) {
            QCoreApplication::removeTranslator(t);
            delete t.data();
        }
    QCoreApplication* app = QCoreApplication::instance();
    return app && (installTranslator(*app) || code == "en");
}

QString installedLanguage()
{
    return installed();
}

}  // namespace taiwa::ui
