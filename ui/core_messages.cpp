// The core's messages in the station's language (core_messages.h): the
// English message matched against the templates of the catalogue, the
// template translated, the arguments put back in.
#include "ui/core_messages.h"

#include "check/messages.h"
#include "tools/tool_library.h"
#include "modules/registry.h"
#include "ui/core_texts.h"
#include "ui/field_spec.h"
#include "ui/profile_editor.h"
#include "ui/language.h"

#include <QCoreApplication>
#include <QFile>
#include <QHash>
#include <QRegularExpression>
#include <QXmlStreamReader>

#include <algorithm>
#include <optional>
#include <vector>

namespace taiwa::ui {

namespace {

constexpr const char* kContext = "taiwa::msg";
// A deeper message in an argument (a tool's name in a refusal in a "step: why") is translated too, so far down.
constexpr int kMaxDepth = 5;

// One of fmt's replacement fields: "{}", "{:g}", "{0}".
const QRegularExpression& placeholder()
{
    static const QRegularExpression re(QStringLiteral(R"(\{[^{}]*\})"));
    return re;
}

struct Template {
    QString source;
    QRegularExpression pattern; // the English message, its arguments captured
    int literal = 0;            // characters outside the placeholders: the more, the more specific
    QString longest;            // its longest run of text, looked for before the expression is tried
    QStringList separators;     // its runs of text between two arguments, of 4 characters or more
};

Template compile(const QString& source)
{
    Template t{source, {}, 0, {}, {}};
    QString pattern = QStringLiteral("^");
    qsizetype at = 0;
    const auto literal = [&](const QString& text) {
        pattern += QRegularExpression::escape(text);
        t.literal += static_cast<int>(text.size());
        if (text.size() > t.longest.size())
            t.longest = text;
    };
    for (auto it = placeholder().globalMatch(source); it.hasNext();) {
        const auto m = it.next();
        const QString text = source.mid(at, m.capturedStart() - at);
        literal(text);
        if (at > 0 && text.size() >= 4) t.separators << text;
        pattern += QStringLiteral("(.*?)");
        at = m.capturedEnd();
    }
    literal(source.mid(at));
    t.pattern = QRegularExpression(pattern + QStringLiteral("$"), QRegularExpression::DotMatchesEverythingOption);
    return t;
}

// The templates of `sources` that have arguments, the most specific first; compiled once for a list.
const std::vector<Template>& compiled(const QStringList& sources)
{
    static QStringList last;
    static std::vector<Template> templates;
    if (sources != last || (templates.empty() && !sources.isEmpty())) {
        last = sources;
        templates.clear();
        for (const QString& s : sources)
            if (placeholder().match(s).hasMatch())
                templates.push_back(compile(s));
        std::stable_sort(templates.begin(), templates.end(),
                         [](const Template& a, const Template& b) { return a.literal > b.literal; });
    }
    return templates;
}

// The translated template with the arguments in: "{}" takes the next one, "{N}" the N-th (from 0).
QString substitute(const QString& translated, const QStringList& args)
{
    QString out;
    qsizetype at = 0;
    int next = 0;
    for (auto it = placeholder().globalMatch(translated); it.hasNext();) {
        const auto m = it.next();
        out += translated.mid(at, m.capturedStart() - at);
        const QString inside = m.captured().mid(1, m.capturedLength() - 2);
        bool indexed = false;
        const int index = inside.toInt(&indexed);
        const int i = indexed ? index : next++;
        out += i >= 0 && i < args.size() ? args[i] : m.captured();
        at = m.capturedEnd();
    }
    return out + translated.mid(at);
}

QString translateText(const QString& text, const QStringList& sources,
                      const std::function<QString(const QString&)>& translate, int depth)
{
    if (text.isEmpty())
        return text;
    if (const QString whole = translate(text); whole != text)
        return whole;
    // Of templates equally specific ("{}: {}", "{}, {}"), the first whose
    // arguments of words all translate; else the first that matched.
    std::optional<QString> fallback;
    int fallbackLiteral = -1;
    for (const Template& t : compiled(sources)) {
        if (fallback && t.literal < fallbackLiteral)
            break;
        if (!text.contains(t.longest))
            continue;
        const auto m = t.pattern.match(text);
        if (!m.hasMatch())
            continue;
        // An argument holding a separator of its own template is a list the
        // template misread ("A on layer 0 (DXF line 5), B on layer 0 (DXF line
        // 9)" read as one entity): another template ("{}, {}") reads it.
        bool misread = false;
        for (int i = 1; i <= m.lastCapturedIndex() && !misread; ++i)
            for (const QString& s : t.separators)
                misread = misread || m.captured(i).contains(s);
        if (misread)
            continue;
        // A translation the same as its source ("T{} ({} Ø{} mm)") is one too: its arguments may be words.
        const QString translated = translate(t.source);
        QStringList args;
        bool whole = true;  // every argument of words came out translated
        for (int i = 1; i <= m.lastCapturedIndex(); ++i) {
            const QString arg = m.captured(i);
            args << (depth < kMaxDepth ? translateText(arg, sources, translate, depth + 1) : arg);
            if (arg.contains(' ') && args.back() == arg) whole = false;
        }
        if (whole)
            return substitute(translated, args);
        if (!fallback) {
            fallback = substitute(translated, args);
            fallbackLiteral = t.literal;
        }
    }
    return fallback.value_or(text);
}

// The known tools' names in other languages, by their name (knowToolNames).
QHash<QString, LocalNames>& toolNames()
{
    static QHash<QString, LocalNames> names = [] {
        QHash<QString, LocalNames> byName;
        for (const Tool& t : defaultToolLibrary())
            if (!t.names.empty()) byName.insert(QString::fromStdString(t.name), t.names);
        return byName;
    }();
    return names;
}

QString translateWord(const QString& text)
{
    if (const auto tool = toolNames().constFind(text); tool != toolNames().constEnd())
        if (const auto name = tool->find(installedLanguage().toStdString()); name != tool->end())
            return QString::fromStdString(name->second);
    const QByteArray source = text.toUtf8();
    const QString msg = QCoreApplication::translate(kContext, source.constData());
    if (msg != text)
        return msg;
    const QString word = QCoreApplication::translate("taiwa::CoreTexts", source.constData());
    if (word != text) return word;
    // A step's label ("Roughing II"): its kind translated, its number as it is (ui/core_texts.h).
    static const QRegularExpression label(QStringLiteral("^(.+) ([IVXLC]+)$"));
    if (const auto m = label.match(text); m.hasMatch())
        if (const QString kind = translateWord(m.captured(1)); kind != m.captured(1)) return kind + " " + m.captured(2);
    return text;
}

} // namespace

QString translateMessage(const QString& english, const QStringList& sources,
                         const std::function<QString(const QString&)>& translate)
{
    return translateText(english, sources, translate, 0);
}

const QStringList& messageSources()
{
    static QString language;
    static QStringList sources;
    if (installedLanguage() == language)
        return sources;
    language = installedLanguage();
    sources.clear();
    QFile file(QStringLiteral(":/i18n/taiwa_%1.ts").arg(language));
    if (language.isEmpty() || !file.open(QIODevice::ReadOnly))
        return sources;
    QXmlStreamReader xml(&file);
    QString context;
    while (!xml.atEnd()) {
        if (!xml.readNextStartElement())
            continue;
        if (xml.name() == QLatin1String("name"))
            context = xml.readElementText();
        else if (xml.name() == QLatin1String("source") && context == QLatin1String(kContext))
            sources << xml.readElementText();
    }
    return sources;
}

QString coreMessage(const std::string& english)
{
    const QString text = QString::fromStdString(english);
    if (messageSources().isEmpty())
        return text;
    return translateMessage(text, messageSources(), translateWord);
}

QString diagnosticText(const std::string& job, const Diagnostic& d)
{
    // As format() does (control characters typed into a name cannot forge
    // lines), but the field as the station names it, in English too
    // ("allowance row 2, Width", not "allowances[2].grooveWidth").
    const auto quoted = [](const QString& s) { return QString::fromStdString(withControlsShown(s.toStdString())); };
    const QString file = quoted(QString::fromStdString(job));
    const QString message = quoted(coreMessage(d.message));
    if (!d.unit && d.field.empty())
        return QCoreApplication::translate("taiwa::ui::Diagnostic", "%1: %2").arg(file, message);
    const QString field = d.field.empty() ? QCoreApplication::translate("taiwa::ui::Diagnostic", "unit")
                                          : quoted(diagnosticField(d));
    const bool warning = d.severity == Severity::Warning;
    if (!d.unit)
        return (warning ? QCoreApplication::translate("taiwa::ui::Diagnostic", "%1: job %2: warning: %3")
                        : QCoreApplication::translate("taiwa::ui::Diagnostic", "%1: job %2: %3"))
            .arg(file, field, message);
    const QString module = quoted(QString::fromStdString(d.module));
    return (warning ? QCoreApplication::translate("taiwa::ui::Diagnostic", "%1: unit %2 (%3) %4: warning: %5")
                    : QCoreApplication::translate("taiwa::ui::Diagnostic", "%1: unit %2 (%3) %4: %5"))
        .arg(file, QString::number(*d.unit), module, field, message);
}

QString diagnosticField(const Diagnostic& d)
{
    const QString field = QString::fromStdString(d.field);
    if (d.unit)
        if (const ModuleKind* kind = findModuleKind(d.module)) {
            // One field of the form: its label; several ("corners": P1 X … P4 Y): the field's own name.
            const FieldSpec* only = nullptr;
            int matches = 0;
            for (const FieldSpec& f : fieldsFor(*kind))
                if (f.diagFields.contains(field)) only = &f, ++matches;
            if (matches == 1) return QCoreApplication::translate("taiwa::ui::FieldSpec", only->label.toUtf8().constData());
            const QString cell = ProfileEditor::cellName(field);
            if (!cell.isEmpty()) return cell;
        }
    return fieldText(d.field);
}

QString toolName(const Tool& tool)
{
    return coreMessage(msg::toolName(tool));
}

QString localName(const std::string& text, const LocalNames& names)
{
    const QString language = installedLanguage();
    return QString::fromStdString(language.isEmpty() ? text : nameIn(names, language.toStdString(), text));
}

QString localToolName(const Tool& tool) { return localName(tool.name, tool.names); }

void knowToolNames(const std::vector<Tool>& tools)
{
    // A tool without names (one the shop named) drops what another of that name had.
    for (const Tool& t : tools) toolNames().insert(QString::fromStdString(t.name), t.names);
}

QString toolKind(ToolType type)
{
    return coreMessage(toString(type));
}

QByteArray translatedDrawing(const QByteArray& svg)
{
    // Each label is the whole text of a <text> element; symbols (P1, r1, T) have no word to translate.
    static const QRegularExpression label(QStringLiteral(R"((<text\b[^>]*>)([^<]*)(</text>))"));
    static const QRegularExpression word(QStringLiteral("[A-Za-z]{2}"));
    const QString in = QString::fromUtf8(svg);
    QString out;
    qsizetype at = 0;
    for (auto it = label.globalMatch(in); it.hasNext();) {
        const auto m = it.next();
        out += in.mid(at, m.capturedStart(2) - at);
        QString text = m.captured(2).trimmed();
        text.replace(QLatin1String("&lt;"), QLatin1String("<")).replace(QLatin1String("&gt;"), QLatin1String(">"));
        text.replace(QLatin1String("&apos;"), QLatin1String("'")).replace(QLatin1String("&quot;"), QLatin1String("\""));
        text.replace(QLatin1String("&amp;"), QLatin1String("&"));
        out += word.match(text).hasMatch()
                   ? QCoreApplication::translate("taiwa::Drawing", text.toUtf8().constData()).toHtmlEscaped()
                   : m.captured(2);
        at = m.capturedEnd(2);
    }
    return (out + in.mid(at)).toUtf8();
}

} // namespace taiwa::ui
