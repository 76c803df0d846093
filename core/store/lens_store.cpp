// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/lens_store.h"

#include "store/sqlite_db.h"
#include "util/host_clock.h"

namespace bs {

using sqlite::Statement;

std::string camera_key(const Frame& frame) {
  std::string key = std::to_string(frame.width) + "x" + std::to_string(frame.height);
  if (frame.is_mosaic())
    key += " " + frame.pattern;
  else
    key += frame.channels == 3 ? " colour" : " grey";
  return key;
}

namespace {

[[noreturn]] void refuse(const Workspace& ws, const std::string& why) {
  throw WorkspaceError(WorkspaceError::Kind::Constraint, ws.path() + ": lens: " + why);
}

SavedLens read_row(const Statement& st) {
  SavedLens s;
  s.frame_id = st.optional_real(0) ? st.int64(0) : 0;
  s.camera = st.text(1);
  s.lens_json = st.text(2);
  s.obtained = st.text(3);
  s.saved_at = st.text(4);
  return s;
}

constexpr const char* kColumns = "SELECT frame_id, camera, lens, obtained, saved_at FROM lenses ";

}  // namespace

void save_lens(Workspace& ws, SavedLens lens) {
  if ((lens.frame_id > 0) == !lens.camera.empty()) refuse(ws, "give either a frame or a camera");
  if (lens.lens_json.empty()) refuse(ws, "no lens to save");
  const sqlite::Db& db = ws.database();
  if (lens.frame_id > 0) {
    Statement probe(db, "SELECT 1 FROM frames WHERE id = ?");
    probe.bind(1, lens.frame_id);
    if (!probe.step()) refuse(ws, "no frame #" + std::to_string(lens.frame_id));
  }
  lens.saved_at = utc_timestamp();
  sqlite::Transaction tx(db);
  remove_lens(ws, lens.frame_id, lens.camera);
  Statement st(db, "INSERT INTO lenses(frame_id, camera, lens, obtained, saved_at) VALUES (?, ?, ?, ?, ?)");
  if (lens.frame_id > 0)
    st.bind(1, lens.frame_id);
  else
    st.bind_null(1);
  const std::string_view camera = lens.frame_id > 0 ? std::string_view("") : std::string_view(lens.camera);
  st.bind(2, camera)
      .bind(3, std::string_view(lens.lens_json))
      .bind(4, std::string_view(lens.obtained))
      .bind(5, std::string_view(lens.saved_at))
      .run();
  tx.commit();
}

void remove_lens(Workspace& ws, std::int64_t frame_id, const std::string& camera) {
  if (frame_id > 0)
    Statement(ws.database(), "DELETE FROM lenses WHERE frame_id = ?").bind(1, frame_id).run();
  else
    Statement(ws.database(), "DELETE FROM lenses WHERE frame_id IS NULL AND camera = ?")
        .bind(1, std::string_view(camera))
        .run();
}

std::optional<SavedLens> find_lens(const Workspace& ws, std::int64_t frame_id, const std::string& camera) {
  const std::string sql =
      std::string(kColumns) + (frame_id > 0 ? "WHERE frame_id = ?" : "WHERE frame_id IS NULL AND camera = ?");
  Statement st(ws.database(), sql.c_str());
  if (frame_id > 0)
    st.bind(1, frame_id);
  else
    st.bind(1, std::string_view(camera));
  if (!st.step()) return std::nullopt;
  return read_row(st);
}

std::vector<SavedLens> saved_lenses(const Workspace& ws) {
  std::vector<SavedLens> out;
  const std::string sql = std::string(kColumns) + "ORDER BY frame_id IS NULL, frame_id, camera";
  Statement st(ws.database(), sql.c_str());
  while (st.step()) out.push_back(read_row(st));
  return out;
}

std::optional<SavedLens> saved_lens_for(const Workspace& ws, const StoredFrame& frame) {
  if (auto own = find_lens(ws, frame.id, {})) return own;
  return find_lens(ws, 0, camera_key(frame.frame));
}

}  // namespace bs
