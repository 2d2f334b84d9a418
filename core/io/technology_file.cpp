// The technology table's file (resources/technology/materials.json) read
// through the one validating reader of data files (io/data_reader.h): a key
// given twice, a key the format does not have, a material id given twice, a
// value out of its range (model/technology_ranges.h) or text that does not
// print is refused, naming the table, the line and the key. Defines
// TechnologyTable::fromJson and ::builtIn (model/technology.h).
#include "builtin_data.h"
#include "io/data_files.h"
#include "io/data_reader.h"
#include "model/local_names_json.h"
#include "model/result.h"
#include "model/technology.h"
#include "model/technology_ranges.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace taiwa {

namespace {

using json = nlohmann::json;

constexpr const char* kTable = "technology table";  // the place every refusal names

class TableReader {
public:
    explicit TableReader(const std::string& text) : r_(text, kTable), text_(text) {}

    std::vector<MaterialTechnology> read()
    {
        const json& root = r_.root();
        onlyKeys(root, "", {"format", "version", "materials"}, "a technology table");
        if (r_.text("format", "") != "taiwa-technology") r_.fail("format", "must be \"taiwa-technology\"");
        if (r_.find(root, "version")) r_.whole("version", 1, 1, 1);
        const json& list = r_.at(root, "materials", "materials");
        if (!list.is_array() || list.empty()) r_.fail("materials", "must be a list of at least one material");
        if (list.size() > kMaxMaterials) r_.fail("materials", "a table holds at most " + std::to_string(kMaxMaterials) + " materials");
        std::vector<MaterialTechnology> out;
        for (std::size_t i = 0; i < list.size(); ++i) {
            try {
                out.push_back(material(list[i], i));
            } catch (const Refusal& r) {  // at the line of the key in this material, not of its first mention
                Place place = r.place();
                if (place.key.starts_with("material ")) place.line = lineIn(i, place.key);
                throw Refusal(r.message(), place);
            }
        }
        return out;
    }

private:
    static constexpr std::size_t kMaxMaterials = 1000;

    MaterialTechnology material(const json& m, std::size_t i)
    {
        const std::string at = "materials[" + std::to_string(i) + "]";  // 0-based, as the reader names a key given twice
        if (!m.is_object()) r_.fail(at, "must be an object");
        MaterialTechnology mt;
        mt.id = r_.text(r_.at(m, "id", at + ".id"), at + ".id", 64, false);
        // From here on the material is named by its id, as the operator knows it.
        const std::string name = "material " + mt.id;
        onlyKeys(m, name + ": ", {"id", "description", "names", "alpha1", "alpha2", "alpha3", "beta2", "gamma", "turning"},
                 "a material");
        if (std::find(seen_.begin(), seen_.end(), mt.id) != seen_.end()) r_.fail(name, "given twice");
        seen_.push_back(mt.id);
        mt.description = m.contains("description") ? r_.text(m["description"], name + ": description", 200, false) : mt.id;
        if (const json* names = r_.find(m, "names")) {
            auto local = localNamesFrom(*names);
            if (!local) r_.fail(name + ": names", local.error());
            for (const auto& [language, text] : *local)
                if (text.size() > 200 || !io::printable(text))
                    r_.fail(name + ": names." + language, "must be printable text of at most 200 bytes");
            mt.names = std::move(*local);
        }
        double* const values[] = {&mt.data.alpha1, &mt.data.alpha2, &mt.data.alpha3, &mt.data.beta2, &mt.data.gamma};
        for (std::size_t k = 0; k < std::size(kTechnologyRanges); ++k)
            *values[k] = number(r_.at(m, kTechnologyRanges[k].key, name + ": " + kTechnologyRanges[k].key), name + ": ",
                                kTechnologyRanges[k]);
        // Turning: optional per material (a table without it turns with the defaults).
        if (const json* t = r_.find(m, "turning")) {
            if (!t->is_object()) r_.fail(name + ": turning", "must be an object");
            std::vector<std::string> keys;
            for (const auto& range : kTurningRanges) keys.push_back(range.key);
            onlyKeys(*t, name + ": turning.", keys, "a material's turning");
            TurningTechnology& turning = mt.data.turning;
            double* const own[] = {&turning.depthOfCut, &turning.allowanceX, &turning.allowanceZ,
                                   &turning.retract,    &turning.clearance,  &turning.withdrawal};
            for (std::size_t k = 0; k < std::size(kTurningRanges); ++k)
                if (const json* v = r_.find(*t, kTurningRanges[k].key))
                    *own[k] = number(*v, name + ": turning.", kTurningRanges[k]);
        }
        return mt;
    }

    // The line of `key`'s last word ("material x: turning.retract": retract)
    // in the i-th material's object, which starts at its i-th "id"; 0 when
    // it is not there.
    int lineIn(std::size_t i, const std::string& key) const
    {
        std::size_t at = text_.find("\"materials\"");
        for (std::size_t k = 0; k <= i && at != std::string::npos; ++k) at = text_.find("\"id\"", at + 1);
        if (at == std::string::npos) return 0;
        const std::size_t cut = key.find_last_of(".: ");
        const std::string last = cut == std::string::npos ? key : key.substr(cut + 1);
        const std::size_t next = text_.find("\"id\"", at + 1);
        const std::size_t keyAt = text_.find("\"" + last + "\"", at);
        return io::lineOfByte(text_, (keyAt != std::string::npos && keyAt < next ? keyAt : at) + 1);
    }

    // A number within its range, low excluded; `prefix` + its key names it.
    double number(const json& v, const std::string& prefix, const TechnologyRange& range) const
    {
        return r_.number(v, prefix + range.key, range.low, range.high, true);
    }

    // Every key of `v` among `keys`: a typo's value would be silently ignored.
    void onlyKeys(const json& v, const std::string& prefix, const std::vector<std::string>& keys, const char* what) const
    {
        for (const auto& [key, value] : v.items())
            if (std::find(keys.begin(), keys.end(), key) == keys.end())
                r_.fail(prefix + key, std::string("not a key of ") + what + " (a typo?)");
    }

    io::DataReader r_;
    const std::string& text_;
    std::vector<std::string> seen_;  // the material ids read so far
};

}  // namespace

TechnologyTable TechnologyTable::fromJson(const std::string& text)
{
    TechnologyTable table;
    table.materials_ = TableReader(text).read();
    return table;
}

const TechnologyTable& TechnologyTable::builtIn()
{
    static const TechnologyTable table = fromJson(builtin::kMaterialsJson);
    return table;
}

}  // namespace taiwa
