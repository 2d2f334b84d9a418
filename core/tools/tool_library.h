// The shop's tool library in SQLite, shared by all jobs (docs/command-line.md "Tool
// library"). Created with the default library on first use. Every failure
// (corrupt file, locked database, read-only folder) is a Failure with a clear
// message; nothing here ever touches a job.
#pragma once

#include "model/result.h"
#include "model/tool.h"
#include "tools/tool_change_log.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace taiwa {

// The realistic default library: centre drills, twist drills 3-20 mm, flat
// end mills 2-25 mm, ball end mills, taper end mills 1-10 deg per side, a face
// mill, a touch probe and the lathe's tools (T101-T107); with cutting data
// for every material of the built-in technology table.
std::vector<Tool> defaultToolLibrary();
// Its lathe tools (T101-T107: OD roughing and finishing inserts, a boring
// bar, grooving and parting blades, a threading insert); a library of an
// older version gets those whose ids are free when it is upgraded.
std::vector<Tool> defaultLatheTools();
// Its tools for hole patterns (module HOLES): tap drills T17-T19, taps
// T61-T67, reaming pre-drills T70-T73, reamers T74-T77, boring heads
// T80-T82; a library of an older version gets those whose ids are free.
std::vector<Tool> defaultHoleTools();

// Where the library lives unless configured: $TAIWA_TOOL_DB, else
// $XDG_DATA_HOME/taiwa/tools.sqlite, else ~/.local/share/taiwa/tools.sqlite.
std::string defaultToolLibraryPath();

// The tools of the library at `path` (opened, and created when missing); a
// server's address (tool_store.h, isServerSetting) reads the shop server.
class ToolLibrary;
Result<std::vector<Tool>> readToolLibrary(const std::string& path);

class ToolLibrary {
public:
    // Opens (creating with the default library when the file does not exist).
    // A failure is a sentence naming the file and what is wrong.
    static Result<ToolLibrary> open(const std::string& path);
    ~ToolLibrary();
    ToolLibrary(ToolLibrary&&) noexcept;
    ToolLibrary(const ToolLibrary&) = delete;
    ToolLibrary& operator=(const ToolLibrary&) = delete;

    const std::string& path() const { return path_; }
    // All tools ordered by id.
    Result<std::vector<Tool>> tools() const;
    // Insert (id 0 = assign a new id) or replace; the tool's id.
    Result<int> save(const Tool& tool);
    Result<void> remove(int id);
    // The tool's edits (saves that changed it, its removal), oldest first:
    // who, where, when, before and after (tool_change_log.h). Cutting minutes
    // added and replaceAll are not edits.
    Result<std::vector<ToolChangeRecord>> history(int id) const;
    // Adds cutting minutes to a tool's used life.
    Result<void> addUsage(int id, double minutes);
    // Every tool replaced by `tools`, in one transaction (the shop server's
    // local copy, tools/pg_tool_store.cpp).
    Result<void> replaceAll(const std::vector<Tool>& tools);

private:
    explicit ToolLibrary(std::string path);
    std::optional<Tool> stored(int id) const;  // the tool of that id as the file holds it
    struct Db;
    std::unique_ptr<Db> db_;
    std::string path_;
};

}  // namespace taiwa
