// The modules' descriptions as data (modules/module_text.h,
// modules/form_binding.h): a description file's refusals name the file and
// the entry; a field binds by its job-file key to the member the table
// names, by its kind; a field nothing binds, a code field without codes,
// codes or a placeholder a field does not take are bugs naming the module;
// the descriptions are the registered modules'; the pockets' codes mean
// what the code tables say; and every field of every shipped module's form
// reads back what it was given on a default unit.
#include "io/unit_keys.h"
#include "modules/form_binding.h"
#include "modules/module_kind.h"
#include "model/codes.h"
#include "modules/registry.h"
#include "support/support.h"

#include <QFile>
#include <QtTest>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

using namespace taiwa;

namespace {

// A module input of one member of each kind the job-file table binds.
struct Toy {
    static constexpr const char* kName = "TOY";
    double depth = 1.0;
    std::optional<double> finish;
    int count = 2;
    int code = 1;
    std::string contour = "K1";
    Point2 corner{3.0, 4.0};
    bool operator==(const Toy&) const = default;
    void convertLengths(const LengthMap&) {}
};

namespace keys = io::keys;
const io::UnitKeys<Toy> kToyKeys{{keys::required("depth", &Toy::depth), keys::optional("finish", &Toy::finish),
                                  keys::whole("count", &Toy::count, 1), keys::whole("code", &Toy::code, 1),
                                  keys::text("contour", &Toy::contour), keys::point("corner", &Toy::corner)}};

// The text `what` thrown by `f` as std::logic_error, or "" if it throws none.
template <class F>
QString logicError(F f)
{
    try {
        f();
    } catch (const std::logic_error& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

const char* kToyForm = R"({"palette": "Add toy", "outline": "corner", "fields": [
    {"key": "depth", "label": "Depth", "help": "How deep"},
    {"key": "finish", "label": "Finish", "placeholder": "the technology data"},
    {"key": "count", "label": "Count"},
    {"key": "code", "label": "Code", "codes": [[1, "one"], [2, "two"]]},
    {"key": "contour", "label": "Contour", "symbol": "sym-contour"},
    {"key": "X1", "label": "X1", "bind": "corner.x", "checks": ["corner"]},
    {"key": "Y1", "label": "Y1", "bind": "corner.y", "checks": ["corner"]}
]})";

// One field "k" bound to "nosuch".
const char* kOne = R"({"palette": "P", "outline": "o", "fields": [{"key": "k", "label": "K", "bind": "nosuch"}]})";

}  // namespace

class TestModuleForms : public QObject {
    Q_OBJECT
private slots:
    void aFieldBindsByItsKeyAndKind()
    {
        const std::vector<FormField> fs = form::boundForm(form::readModuleText(kToyForm, "toy.module.json").fields, &kToyKeys);
        QCOMPARE(fs.size(), std::size_t(7));
        ModuleInput unit = Toy{};
        // A number: read and written.
        QCOMPARE(fs[0].kind, FormFieldKind::Number);
        QCOMPARE(fs[0].help, std::string("How deep"));
        fs[0].set(unit, 7.5);
        QCOMPARE(unit.as<Toy>().depth, 7.5);
        // An optional number: empty is none, the placeholder the file's.
        QCOMPARE(fs[1].kind, FormFieldKind::OptionalNumber);
        QCOMPARE(fs[1].placeholder, std::string("the technology data"));
        fs[1].set(unit, 0.25);
        QCOMPARE(*unit.as<Toy>().finish, 0.25);
        fs[1].set(unit, std::nullopt);
        QVERIFY(!unit.as<Toy>().finish);
        // A whole number without codes is a count, refusing fractions; with codes, a code.
        QCOMPARE(fs[2].kind, FormFieldKind::Number);
        QVERIFY(fs[2].whole);
        QCOMPARE(fs[3].kind, FormFieldKind::Code);
        QCOMPARE(fs[3].codes.size(), std::size_t(2));
        QCOMPARE(fs[3].codes[1].second, std::string("two"));
        fs[3].set(unit, 2.0);
        QCOMPARE(unit.as<Toy>().code, 2);
        // A text is a contour's name, blanks dropped.
        QCOMPARE(fs[4].kind, FormFieldKind::ContourName);
        fs[4].setText(unit, "  K7 ");
        QCOMPARE(unit.as<Toy>().contour, std::string("K7"));
        QCOMPARE(fs[4].symbol, std::string("sym-contour"));
        // A point's coordinate, by "corner.x", its check field the file's.
        QCOMPARE(*fs[5].get(unit), 3.0);
        fs[6].set(unit, -2.0);
        QCOMPARE(unit.as<Toy>().corner.y, -2.0);
        QCOMPARE(fs[6].diagFields, std::vector<std::string>{"corner"});
        QCOMPARE(fs[2].diagFields, std::vector<std::string>{"count"});
    }

    void aFieldNothingBindsIsABugNamingTheModule()
    {
        for (const char* bind : {"nosuch", "corner", "depth.x", "corner.z"}) {
            const std::string text = std::string(R"({"palette": "P", "outline": "o", "fields": [{"key": "k", "label": "K", "bind": ")") +
                                     bind + "\"}]}";
            const QString why =
                logicError([&] { form::boundForm(form::readModuleText(text, "toy.module.json").fields, &kToyKeys); });
            QVERIFY2(why.contains("module TOY") && why.contains(QString("\"%1\"").arg(bind)), qPrintable(why));
        }
        // The door's own binding comes first.
        const auto own = [](const form::FieldText& t) -> std::optional<FormField> {
            if (t.bind != "nosuch") return std::nullopt;
            return form::number<Toy>(t.key, t.label, t.checks, [](const Toy& y) { return y.depth * 2; }, [](Toy&, double) {});
        };
        const auto fs = form::boundForm(form::readModuleText(kOne, "toy.module.json").fields, &kToyKeys, own);
        QCOMPARE(*fs[0].get(ModuleInput(Toy{})), 2.0);
        // Codes on a number, a placeholder on a field that cannot be empty.
        const std::pair<const char*, const char*> kWrong[] = {
            {R"({"key": "depth", "label": "D", "codes": [[1, "one"]]})",
             "the form of module TOY gives field \"depth\" codes, but it is not a code"},
            {R"({"key": "count", "label": "N", "placeholder": "none"})",
             "the form of module TOY gives field \"count\" a placeholder, but it cannot be empty"}};
        for (const auto& [field, expected] : kWrong) {
            const std::string text = std::string(R"({"palette": "P", "outline": "o", "fields": [)") + field + "]}";
            const QString why =
                logicError([&] { form::boundForm(form::readModuleText(text, "toy.module.json").fields, &kToyKeys); });
            QCOMPARE(why, QString(expected));
        }
        // A code field with no codes.
        const QString why = logicError([] {
            form::boundForm(form::readModuleText(kOne, "toy").fields, &kToyKeys,
                            [](const form::FieldText& t) -> std::optional<FormField> {
                                FormField f = form::intMember<Toy>(t.key, t.label, &Toy::code);  // no codes
                                f.kind = FormFieldKind::Code;
                                return f;
                            });
        });
        QVERIFY2(why.contains("code field \"k\" with no codes"), qPrintable(why));
    }

    void aBadDescriptionIsRefusedWhere_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("expected");
        // Every row but the first six: a description with these fields.
        const auto with = [](const char* fields) {
            return QString(R"({"palette": "Add toy", "outline": "o", "fields": [%1]})").arg(fields);
        };
        QTest::newRow("not JSON") << "{\"fields\": [" << "x.module.json: [json.exception.parse_error";
        QTest::newRow("a part twice") << R"({"palette": "P", "palette": "Q", "outline": "o", "fields": []})"
                                      << "x.module.json: palette is given twice";
        QTest::newRow("a property twice") << R"({"palette": "P", "outline": "o", "fields": [{"key": "a", "label": "A", "label": "B"}]})"
                                          << "x.module.json: fields[0].label is given twice";
        QTest::newRow("no fields") << "{\"field\": []}" << "x.module.json: not an object with a list \"fields\"";
        QTest::newRow("no palette") << R"({"outline": "o", "fields": []})"
                                    << "x.module.json: no \"palette\" or no \"outline\"";
        QTest::newRow("a part it lacks") << R"({"palette": "P", "outline": "o", "fields": [], "drawing": "x"})"
                                         << "x.module.json: \"drawing\" is not a part of a module's description";
        QTest::newRow("a typo") << with(R"({"key": "a", "lable": "A"})")
                                << "x.module.json: field 1 has \"lable\", which a field does not have";
        QTest::newRow("no label") << with(R"({"key": "a", "label": "A"}, {"key": "b"})")
                                  << "x.module.json: field 2 has no key or no label";
        QTest::newRow("twice") << with(R"({"key": "a", "label": "A"}, {"key": "a", "label": "B"})")
                               << "x.module.json: field 2: key \"a\" twice";
        QTest::newRow("a label not text") << with(R"({"key": "a", "label": 3})")
                                          << "x.module.json: field 1: \"label\" is not a text";
        QTest::newRow("a code") << with(R"({"key": "a", "label": "A", "codes": [[1, 2]]})")
                                << "x.module.json: field 1: a code is not [value, \"meaning\"] nor a value";
        QTest::newRow("a value with no meaning") << with(R"({"key": "a", "label": "A", "codes": [1]})")
                                                 << "x.module.json: field 1 (a): code 1 has no meaning";
        QTest::newRow("no shared field") << with(R"({"shared": "nosuch"})")
                                         << "x.module.json: field 1: no shared field \"nosuch\"";
        QTest::newRow("a shared code it lacks") << with(R"({"shared": "u", "codes": [1, 7]})")
                                                << "x.module.json: field 1 (U): code 7 has no meaning";
        QTest::newRow("no codes") << with(R"({"shared": "u", "codes": []})")
                                  << "x.module.json: field 1: \"codes\" is not a list of codes";
        QTest::newRow("no checks") << with(R"({"key": "a", "label": "A", "checks": []})")
                                   << "x.module.json: field 1: \"checks\" is not a list of names";
        QTest::newRow("a code twice") << with(R"({"key": "a", "label": "A", "codes": [[1, "one"], [1, "uno"]]})")
                                      << "x.module.json: field 1: code 1 twice";
        QTest::newRow("shared twice") << with(R"({"shared": "v"})")
                                      << "shared_fields.json: v has \"shared\", which a field does not have";
    }
    void aBadDescriptionIsRefusedWhere()
    {
        QFETCH(QString, text);
        QFETCH(QString, expected);
        const char* shared = R"j({"u": {"key": "U", "label": "U (tool use)", "codes": [[1, "all"], [9, "roughing"]]},
                                  "v": {"shared": "u"}})j";
        const QString why = logicError([&] { form::readModuleText(text.toStdString(), "x.module.json", shared); });
        QVERIFY2(why.startsWith("module description " + expected), qPrintable(why));
    }

    // A shared entry with a module's own codes, by value: their meanings the shared ones.
    void aSharedFieldTakesItsOwnCodes()
    {
        const char* shared = R"j({"u": {"key": "U", "label": "U (tool use)", "codes": [[1, "all"], [9, "roughing"]]}})j";
        const auto fs =
            form::readModuleText(R"({"palette": "P", "outline": "o", "fields": [{"shared": "u", "codes": [9], "help": "Which"}]})",
                                 "x", shared)
                .fields;
        QCOMPARE(fs.size(), std::size_t(1));
        QCOMPARE(fs[0].key, std::string("U"));
        QCOMPARE(fs[0].codes, (std::vector<std::pair<int, std::string>>{{9, "roughing"}}));
        QCOMPARE(fs[0].help, std::string("Which"));
        QCOMPARE(fs[0].checks, std::vector<std::string>{"U"});
    }

    // Every registered module has its description file, and every file a module.
    void theDescriptionsAreTheModules()
    {
        std::vector<std::string> modules;
        for (const ModuleKind* kind : moduleKinds()) {
            std::string folder = kind->name();
            for (char& c : folder) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            modules.push_back(folder);
            // Its drawing is a file of its folder (a resource of the station).
            const QString drawing = QString::fromUtf8(kind->drawing());
            QVERIFY2(QFile::exists(test::sourcePath("core/modules/" + QString::fromStdString(folder) + "/" + drawing.mid(10))),
                     qPrintable(drawing));
        }
        std::vector<std::string> folders = form::shippedModuleFolders();
        std::sort(modules.begin(), modules.end());
        std::sort(folders.begin(), folders.end());
        QCOMPARE(folders, modules);
    }

    // The pockets' codes U, F and H mean in their forms what the code tables
    // say (model/codes.h), the texts the sheet and the messages use.
    void thePocketCodesMeanWhatTheTablesSay()
    {
        int compared = 0;
        for (const char* name : {"M4", "M2D", "CP"})
            for (const FormField& f : findModuleKind(name)->fields())
                for (const auto& [value, text] : f.codes) {
                    const std::string_view table = f.key == "U"   ? meaning(ToolUse(value))
                                                   : f.key == "F" ? meaning(WallFinish(value))
                                                   : f.key == "H" ? meaning(PilotHole(value))
                                                                  : std::string_view(text);
                    QCOMPARE(text, std::string(table));
                    ++compared;
                }
        QCOMPARE(compared, 5 + 3 + 2 + 2 + 2 + 4 + 3);
    }

    // Every field of every shipped form reads back, on a default unit, what
    // it was given: a number, each code offered, a name, and empty where it
    // may be.
    void everyShippedFieldReadsBackWhatItWasGiven()
    {
        int checked = 0;
        for (const ModuleKind* kind : moduleKinds()) {
            const ModuleInput unit = kind->makeDefault(Stock{});
            for (const FormField& f : kind->fields()) {
                const QString where = QString("%1 %2").arg(kind->name(), QString::fromStdString(f.key));
                ModuleInput copy = unit;
                if (f.kind == FormFieldKind::ContourName) {
                    f.setText(copy, "K9");
                    QVERIFY2(f.getText(copy) == "K9", qPrintable(where));
                } else if (f.kind == FormFieldKind::ContourNames) {
                    f.setText(copy, "K8 K9");
                    QVERIFY2(f.getText(copy) == "K8, K9", qPrintable(where));
                } else if (f.kind == FormFieldKind::Points) {
                    f.setText(copy, f.getText(unit));  // its own text, as it showed it
                    QVERIFY2(f.getText(copy) == f.getText(unit), qPrintable(where));
                } else if (f.kind == FormFieldKind::Code) {
                    QVERIFY2(!f.codes.empty(), qPrintable(where));
                    for (const auto& [value, meaning] : f.codes) {
                        f.set(copy, value);
                        QVERIFY2(f.get(copy) && *f.get(copy) == value, qPrintable(where + " " + QString::number(value)));
                    }
                } else {
                    f.set(copy, 7.0);
                    QVERIFY2(f.get(copy) && *f.get(copy) == 7.0, qPrintable(where));
                    if (f.kind == FormFieldKind::OptionalNumber) {
                        f.set(copy, std::nullopt);
                        QVERIFY2(!f.get(copy), qPrintable(where + " empty"));
                    }
                }
                QVERIFY2(!f.label.empty(), qPrintable(where));
                ++checked;
            }
        }
        QVERIFY(checked > 100);
    }
};

QTEST_GUILESS_MAIN(TestModuleForms)
#include "test_module_forms.moc"
