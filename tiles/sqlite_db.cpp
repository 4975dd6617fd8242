#include "tiles/sqlite_db.h"

#include <sqlite3.h>

#include "tiles/file_io.h"

namespace skylit::tiles::detail {

Database::Database(const std::filesystem::path& path, bool read_only) : path_(path) {
  const int flags = read_only ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE;
  if (sqlite3_open_v2(path.c_str(), &db_, flags, nullptr) != SQLITE_OK) {
    const std::string msg = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    db_ = nullptr;
    detail::fail(path_, "cannot open as SQLite: " + msg);
  }
  sqlite3_extended_result_codes(db_, 0);
}

Database::~Database() {
  if (db_) sqlite3_close_v2(db_);  // an open transaction is rolled back
}

void Database::exec(const char* sql) {
  char* err = nullptr;
  if (sqlite3_exec(db_, sql, nullptr, nullptr, &err) != SQLITE_OK) {
    const std::string msg = err ? err : sqlite3_errmsg(db_);
    sqlite3_free(err);
    detail::fail(path_, msg);
  }
}

void Database::close() {
  if (sqlite3_close(db_) != SQLITE_OK) fail("cannot close");
  db_ = nullptr;
}

void Database::fail(const std::string& what) const {
  detail::fail(path_, what + ": " + sqlite3_errmsg(db_));
}

Statement::Statement(Database& db, const char* sql) : db_(db) {
  if (sqlite3_prepare_v2(db.handle(), sql, -1, &stmt_, nullptr) != SQLITE_OK)
    db.fail("cannot prepare '" + std::string(sql) + "'");
}

Statement::~Statement() { sqlite3_finalize(stmt_); }

Statement& Statement::bind(int i, std::int64_t v) {
  if (sqlite3_bind_int64(stmt_, i, v) != SQLITE_OK) db_.fail("cannot bind");
  return *this;
}

Statement& Statement::bind(int i, const std::string& text) {
  if (sqlite3_bind_text(stmt_, i, text.data(), static_cast<int>(text.size()), SQLITE_TRANSIENT) !=
      SQLITE_OK)
    db_.fail("cannot bind");
  return *this;
}

Statement& Statement::bind_blob(int i, std::span<const std::byte> blob) {
  // SQLITE_STATIC: the caller's bytes outlive the step() that reads them.
  if (sqlite3_bind_blob64(stmt_, i, blob.data(), blob.size(), SQLITE_STATIC) != SQLITE_OK)
    db_.fail("cannot bind");
  return *this;
}

bool Statement::step() {
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  const std::string msg = sqlite3_errmsg(db_.handle());
  sqlite3_reset(stmt_);
  detail::fail(db_.path(), msg);
}

void Statement::reset() {
  sqlite3_reset(stmt_);
  sqlite3_clear_bindings(stmt_);
}

std::int64_t Statement::column_int(int i) const { return sqlite3_column_int64(stmt_, i); }

std::string Statement::column_text(int i) const {
  const auto* p = static_cast<const char*>(sqlite3_column_blob(stmt_, i));
  return p ? std::string(p, static_cast<std::size_t>(sqlite3_column_bytes(stmt_, i))) : std::string();
}

// SQLite itself says whether a transaction is open: after SQLITE_FULL it may have
// rolled the whole batch back on its own.
void Batcher::begin() {
  if (sqlite3_get_autocommit(db_.handle())) {
    db_.exec("BEGIN");
    pending_ = 0;
  }
}

void Batcher::wrote() {
  if (++pending_ >= batch_) commit();
}

void Batcher::commit() {
  if (!sqlite3_get_autocommit(db_.handle())) db_.exec("COMMIT");
  pending_ = 0;
}

}  // namespace skylit::tiles::detail
