// A thin RAII layer over SQLite for the MBTiles archive and the PMTiles staging
// database: errors become TileArchiveError naming the database file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

struct sqlite3;
struct sqlite3_stmt;

namespace skylit::tiles::detail {

class Database;

class Statement {
 public:
  Statement(Database& db, const char* sql);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  // Parameters are numbered from 1, as in SQLite.
  Statement& bind(int i, std::int64_t v);
  Statement& bind(int i, const std::string& text);
  Statement& bind_blob(int i, std::span<const std::byte> blob);
  bool step();  // true: a row is ready; false: done (then reset() before the next use)
  void reset();
  std::int64_t column_int(int i) const;
  std::string column_text(int i) const;  // blobs too: their bytes
  void run() {  // one step of a statement that returns no row, then reset
    step();
    reset();
  }

 private:
  Database& db_;
  sqlite3_stmt* stmt_ = nullptr;
};

class Database {
 public:
  // Opens (creating if absent) the database file; a hot journal left by a killed
  // writer is rolled back by SQLite here, so only committed transactions remain.
  explicit Database(const std::filesystem::path& path, bool read_only = false);
  ~Database();
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;
  void exec(const char* sql);
  // Commits and closes, reporting errors (the destructor only rolls back and closes).
  void close();
  [[noreturn]] void fail(const std::string& what) const;  // what + SQLite's message
  sqlite3* handle() const { return db_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  sqlite3* db_ = nullptr;
};

// Groups writes into transactions of `batch` statements: one commit per batch is what
// makes SQLite fast, and a kill -9 loses at most the uncommitted batch, never a tile
// half-written (SQLite's rollback journal).
class Batcher {
 public:
  Batcher(Database& db, int batch) : db_(db), batch_(batch > 0 ? batch : 1) {}
  void begin();   // before each write: opens a transaction when none is open
  void wrote();   // after each write: commits when the batch is full
  void commit();  // commits what is open (nothing when none is)

 private:
  Database& db_;
  int batch_, pending_ = 0;
};

}  // namespace skylit::tiles::detail
