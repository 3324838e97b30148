// Placeholders in adapter commands ("{build}/tracer", "--out={image}"): which exist, where each
// may be used, how a template is checked, and how it is expanded. Expansion is plain text
// substitution per argv element; nothing is ever handed to a shell, so a branch name or path
// holding `;` or `$(...)` reaches the tracer as those very characters.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raygate {

// Where a template is used decides which placeholders it may hold: build steps run once per
// commit, before any scene exists, so {scene}, {image}, {threads} ... mean nothing there.
enum class TemplateField {
  build,  // "build" steps
  run,    // "run", "stdin", "cwd", "image", "env" values
};

// The values of one expansion. Unset means "not known here"; expanding a template that uses an
// unset placeholder is a programming error (validation keeps it from user input).
struct Placeholders {
  std::optional<std::string> src;             // checked-out source dir (repo_root/source_dir)
  std::optional<std::string> repo_root;       // root of the checked-out worktree
  std::optional<std::string> build;           // build directory of this commit
  std::optional<std::string> jobs;            // parallel build jobs
  std::optional<std::string> threads;         // thread count for the run
  std::optional<std::string> scene;           // scene file, in the adapter's scene_format
  std::optional<std::string> image;           // where raygate wants the image: in workdir, .png
  std::optional<std::string> workdir;         // fresh, empty working directory of this run
  std::optional<std::string> raygate_source;  // raygate's own source tree
  std::optional<std::string> scene_stem;      // scene file name without directory or extension
  std::optional<std::string> width;           // the scene's image width in pixels (its NFF view)
  std::optional<std::string> height;          // the scene's image height in pixels
  // A different number for every run ("images": "monte-carlo" adapters only): a hash of the
  // run's own directory, which is new for every measurement.
  std::optional<std::string> seed;

  // The value for a placeholder name ("scene"), or nullptr if the name is unknown.
  const std::optional<std::string>* find(std::string_view name) const;
};

// Every placeholder name, in documentation order, without braces.
const std::vector<std::string>& placeholder_names();
// The names allowed in `field`, in documentation order.
const std::vector<std::string>& placeholders_allowed_in(TemplateField field);

// Why `text` is not a valid template for `field` ("unknown placeholder '{scen}' (did you mean
// '{scene}'?)", "unmatched '{' ..."), or nullopt if it is valid.
std::optional<std::string> template_error(std::string_view text, TemplateField field);

// True if a valid template uses {name} somewhere (escaped "{{name}}" does not count).
bool uses_placeholder(std::string_view text, std::string_view name);

// Substitutes placeholders in one element; "{{" and "}}" become "{" and "}". Substituted values
// are not scanned again. Throws std::logic_error for a malformed template or an unset value.
std::string expand(std::string_view text, const Placeholders& values);
std::vector<std::string> expand(const std::vector<std::string>& argv, const Placeholders& values);

}  // namespace raygate
