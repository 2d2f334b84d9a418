// Files on disk for the job reader and every export: reading a text file
// with its size checked before it is read into memory, writing any text
// atomically (temporary file in the same folder, fsync, rename), and
// replacing a set of files together.
#pragma once

#include "model/diagnostic.h"
#include "model/result.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace taiwa {

namespace io {

struct TextReadResult {
    std::optional<std::string> text;  // present when the file was read whole
    Diagnostics diagnostics;          // why not: one diagnostic about the file as a whole
};

// A regular file of at most maxBytes, read whole; anything else refused.
TextReadResult readTextFile(const std::string& path, std::size_t maxBytes);

}  // namespace io

// Writes text to path atomically: a temporary file in the same folder,
// synced, then renamed over the old one.
Result<void> writeFileAtomically(const std::string& path, std::string_view text);

// A set of files in one folder replaced together (an export: tape, sheet,
// steps). Each file is written at once to a temporary beside its target,
// created exclusively under a name of its own (never following a link
// planted there), written to the last byte and synced. commit() first
// writes a journal (.STEM.set: each temporary and its target, each file of
// the old set to remove), then renames them all over the old ones and
// removes the files the set no longer has (another dialect's tape), then
// the journal; a rename that fails puts the old ones back. A process killed
// between two renames leaves the journal: the next open() of the stem rolls
// it forward, so the folder never keeps half of one set beside half of
// another. A set not committed removes its temporaries. Sets of one stem in
// one folder are serialised by a lock file kept outside that folder (in the
// user's runtime folder, $XDG_RUNTIME_DIR, else the temporary folder:
// lockPathFor), so that the folder holds nothing but the set; temporaries
// of that stem left by a process that died are removed when the next set
// is opened.
class FileSet {
public:
    // Takes the folder's lock for `stem` (waits for another set of it).
    static Result<FileSet> open(const std::string& folder, const std::string& stem);
    // The lock file of `stem` in `folder`: one per canonical folder and
    // stem, in the user's runtime folder (created if missing).
    static Result<std::string> lockPathFor(const std::string& folder, const std::string& stem);
    FileSet(FileSet&& other) noexcept;
    FileSet& operator=(FileSet&&) = delete;
    ~FileSet();

    // Writes `bytes` to the temporary of folder/name.
    Result<void> add(const std::string& name, std::string_view bytes);
    // folder/name, when it exists, is removed by commit() with the renames
    // (a file of the old set the new one does not have).
    void remove(const std::string& name);
    // Renames every temporary over its target and removes what remove()
    // named; the paths written, in order. `between` (tests only) is called
    // after each rename, with how many are done: a test ends the process there.
    Result<std::vector<std::string>> commit(const std::function<void(std::size_t)>& between = {});

private:
    FileSet(std::string folder, std::string stem, int lock);
    struct Staged {
        std::string target, temp;
    };
    std::string folder_, stem_;
    int lock_ = -1;
    std::vector<Staged> staged_;
    std::vector<std::string> removals_;
};

}  // namespace taiwa
