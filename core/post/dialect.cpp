// The table of dialects and its lookups (post.h: dialectNames, isDialect).
#include "post/dialect.h"

#include "post/post.h"

#include <array>

namespace taiwa::post {

namespace {
std::array<const Dialect*, 2> table() { return {&fanucDialect(), &linuxcncDialect()}; }
}  // namespace

const Dialect* findDialect(const std::string& name)
{
    for (const Dialect* d : table())
        if (d->name == name) return d;
    return nullptr;
}

}  // namespace taiwa::post

namespace taiwa {

std::vector<std::string> dialectNames()
{
    std::vector<std::string> names;
    for (const post::Dialect* d : post::table()) names.push_back(d->name);
    return names;
}

bool isDialect(const std::string& name) { return post::findDialect(name) != nullptr; }

}  // namespace taiwa
