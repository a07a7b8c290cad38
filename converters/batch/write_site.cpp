#include "converters/batch/write_site.hpp"

#include <filesystem>
#include <iostream>

#include "converters/batch/worker_pool.hpp"
#include "formats/common/file_io.hpp"
#include "formats/common/gzip.hpp"
#include "formats/png/indexed_png.hpp"
#include "formats/web_text/markup_text.hpp"
#include "web/api/scene_arrays.hpp"
#include "web/page/site_page.hpp"
#include "web/thumbnail/part_thumbnail.hpp"

namespace cadnurbs {

namespace fs = std::filesystem;

namespace {

// A file of the site, written only when its bytes change (a second run leaves the site's dates alone);
// whether it was written.
bool write_if_changed(const fs::path& path, const std::string& bytes) {
  std::error_code error;
  if (fs::is_regular_file(path, error) && fs::file_size(path, error) == bytes.size() && read_file(path.string()) == bytes) return false;
  fs::create_directories(path.parent_path());
  write_file_atomically(path.string(), bytes);
  return true;
}

SiteFileSize file_size_of(const std::string& label, const fs::path& path) {
  const std::string bytes = read_file(path.string());
  return {label, static_cast<long>(bytes.size()), static_cast<long>(gzip(bytes).size())};
}

// The part's folder in the library: its path's first folder ("" at the top).
std::string family_of(const std::string& relative) {
  const size_t slash = relative.find('/');
  return slash == std::string::npos ? "" : relative.substr(0, slash);
}

// From a page at `relative` (under the site's top) back to the top: "../" per folder.
std::string root_of(const std::string& relative) {
  std::string root;
  for (const char c : relative)
    if (c == '/') root += "../";
  return root;
}

// The site's title: the library folder's name ("lib/" and "lib" alike).
std::string library_title(const std::string& in_dir) {
  fs::path folder = fs::path(in_dir).lexically_normal();
  if (folder.filename().empty()) folder = folder.parent_path();
  return folder.filename().string();
}

// What a part's site files are: its .cnb copy, page and picture, beside each other.
struct SiteFiles {
  fs::path cnb, page, picture, error;  // error: beside the batch's outputs, the picture's failure when it failed
};

SiteFiles site_files(const SiteOptions& options, const std::string& relative) {
  const fs::path stem = output_stem(options.site_dir, relative);
  return {stem.string() + ".cnb", stem.string() + ".html", stem.string() + ".png",
          output_stem(options.out_dir, relative).string() + ".site-error"};
}

// The part's page (written only when it changed), beside its .cnb of `cnb_bytes` bytes and its picture,
// which the page shows until the viewer draws, when there is one.
void write_part_page(const SiteFiles& files, const std::string& relative, const std::string& library, long cnb_bytes) {
  SitePartPage page;
  page.name = fs::path(relative).filename().string();
  page.family = family_of(relative);
  page.library = library;
  page.cnb_file = files.cnb.filename().string();
  page.cnb_bytes = cnb_bytes;
  std::error_code missing;
  if (fs::is_regular_file(files.picture, missing)) page.picture_file = files.picture.filename().string();
  page.root = root_of(relative);
  write_if_changed(files.page, site_part_page(page));
}

// In a worker: the part's picture, its .cnb read back and meshed as the page's viewer does (web/api), at
// site_thumbnail_deviation of its diagonal. A picture that cannot be made leaves its reason in files.error
// and exit status 1; the page stands without it.
int write_part_picture(const SiteOptions& options, const std::string& relative) {
  const SiteFiles files = site_files(options, relative);
  try {
    const Scene scene = read_scene_bytes(read_file(files.cnb.string()), files.cnb.string());
    const SceneArrays mesh = certified_scene_arrays(scene, site_thumbnail_deviation * scene_diagonal(scene));
    write_if_changed(files.picture, indexed_png(part_thumbnail(mesh, site_thumbnail_width, site_thumbnail_height)));
    return 0;
  } catch (const std::exception& error) {
    std::error_code ignored;
    fs::remove(files.picture, ignored);
    write_file_atomically(files.error.string(), error.what());
    return 1;
  }
}

}  // namespace

std::string library_mesh_beside(const std::string& part_path) {
  const fs::path part(part_path);
  for (const char* extension : {".wrl", ".wrz", ".x3d", ".stl"}) {
    fs::path mesh = part;
    mesh.replace_extension(extension);
    std::error_code error;
    if (mesh != part && fs::is_regular_file(mesh, error)) return mesh.string();
  }
  return "";
}

SiteSummary write_site(const SiteOptions& options, const std::vector<LibraryPart>& parts, const std::vector<PartRecord>& records) {
  std::error_code error;
  fs::create_directories(options.site_dir, error);
  if (error || !fs::is_directory(options.site_dir)) throw FileError(options.site_dir + ": cannot be made a folder");
  const fs::path assets = fs::path(options.site_dir) / site_assets_folder();
  SiteSummary summary;
  for (const auto& [name, bytes] : site_assets()) {
    write_if_changed(assets / name, bytes);
    summary.totals.shared += static_cast<long>(bytes.size());
    summary.totals.gzip += static_cast<long>(gzip(bytes).size());
  }
  const std::string library = library_title(options.in_dir);

  // Pictures cost a meshing: only those of new parts or of a .cnb that changed (its copy in the site
  // rewritten). Pages are cheap and follow this cadnurbs' template: all written (when changed), after the
  // pictures, which they show.
  std::vector<size_t> to_write;
  std::vector<long> cnb_bytes(parts.size(), 0);
  for (size_t i = 0; i < parts.size(); ++i) {
    if (records[i].failed) continue;
    const SiteFiles files = site_files(options, parts[i].relative);
    const std::string cnb = read_file(output_stem(options.out_dir, parts[i].relative).string() + ".cnb");
    cnb_bytes[i] = static_cast<long>(cnb.size());
    std::error_code missing;
    if (write_if_changed(files.cnb, cnb) || !fs::is_regular_file(files.picture, missing)) to_write.push_back(i);
  }
  std::vector<std::string> picture_errors(parts.size());
  run_in_workers(
      static_cast<int>(to_write.size()), options.jobs, options.limits,
      [&](int k) { return write_part_picture(options, parts[to_write[k]].relative); },
      [&](int k, const WorkerOutcome& outcome) {
        const size_t i = to_write[k];
        const SiteFiles files = site_files(options, parts[i].relative);
        std::string reason = outcome.reason(options.limits);
        std::error_code missing;
        if (fs::is_regular_file(files.error, missing)) {
          reason = read_file(files.error.string());
          fs::remove(files.error, missing);
        }
        if (!reason.empty()) {
          picture_errors[i] = "no picture: " + reason;
          std::cerr << "batch: site: " << parts[i].relative << ": " << picture_errors[i] << "\n";
        }
      });
  for (size_t i = 0; i < parts.size(); ++i)
    if (!records[i].failed) write_part_page(site_files(options, parts[i].relative), parts[i].relative, library, cnb_bytes[i]);

  std::vector<SiteIndexEntry> entries;
  for (size_t i = 0; i < parts.size(); ++i) {
    SiteIndexEntry entry;
    entry.part = parts[i].relative;
    entry.family = family_of(parts[i].relative);
    const std::string library_mesh = library_mesh_beside((fs::path(options.in_dir) / parts[i].relative).string());
    if (!library_mesh.empty()) {
      entry.has_library_mesh = true;
      entry.library_mesh = file_size_of(fs::path(library_mesh).extension().string(), library_mesh);
      summary.totals.library_mesh += entry.library_mesh.bytes;
      summary.totals.library_mesh_gzip += entry.library_mesh.gzip_bytes;
      ++summary.totals.parts_with_library_mesh;
    }
    if (records[i].failed) {
      entry.error = records[i].error;
      entries.push_back(std::move(entry));
      continue;
    }
    const SiteFiles files = site_files(options, parts[i].relative);
    std::error_code missing;
    if (fs::is_regular_file(files.page, missing)) {
      ++summary.pages;
      entry.page = url_path(parts[i].relative + ".html");
      const SiteFileSize page = file_size_of("page", files.page);
      summary.totals.pages += page.bytes;
      summary.totals.gzip += page.gzip_bytes;
    }
    if (fs::is_regular_file(files.picture, missing)) {
      entry.thumbnail = url_path(parts[i].relative + ".png");
      const SiteFileSize picture = file_size_of("picture", files.picture);
      summary.totals.thumbnails += picture.bytes;
      summary.totals.gzip += picture.gzip_bytes;
    } else {
      ++summary.pictures_failed;
      entry.error = picture_errors[i].empty() ? "no picture" : picture_errors[i];
    }
    const SiteFileSize cnb = file_size_of(".cnb", files.cnb);
    summary.totals.cnb += cnb.bytes;
    summary.totals.gzip += cnb.gzip_bytes;
    entry.files.push_back(cnb);
    for (const auto& r : records[i].representations)
      if (r.key != "cnb") entry.files.push_back({"." + r.key, r.bytes, r.gzip_bytes});
    entries.push_back(std::move(entry));
  }
  // The index counts itself: its size is said in it, so settle the text and its length together.
  const std::string licences = url_path(std::string(site_assets_folder()) + "/LICENSES.txt");
  const long gzip_without_index = summary.totals.gzip;
  std::string index;
  for (int pass = 0; pass < 8; ++pass) {
    std::string text = site_index_html(library, entries, summary.totals, licences);
    if (text == index) break;
    index = std::move(text);
    summary.totals.index = static_cast<long>(index.size());
    summary.totals.gzip = gzip_without_index + static_cast<long>(gzip(index).size());
  }
  write_if_changed(fs::path(options.site_dir) / "index.html", index);
  return summary;
}

}  // namespace cadnurbs
