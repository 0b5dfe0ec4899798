#include "app/completion_command.h"

#include <fmt/format.h>

#include <iostream>
#include <string>
#include <vector>

#include "app/flag_checks.h"
#include "core/input_error.h"
#include "db/study_queries.h"
#include "formats/json_reader.h"

namespace shockmap {
namespace {

// The hidden command the script runs to list the stored studies (`completion study-names`).
constexpr const char* kStudyNamesCommand = "study-names";

// An option's value completion: a fixed list, folder names, or (neither) file names.
struct ValueCompletion {
  std::string option;
  std::vector<std::string> choices;
  bool folders = false;
};

// One command path ("", " study", " study run") with the words that may follow it.
struct CompletionNode {
  std::string path;
  std::vector<std::string> words;          // subcommands, then options
  std::vector<std::string> value_options;  // options followed by a value (a file, a number)
  std::vector<ValueCompletion> values;     // those whose values are listed, or are folders
  bool study_name = false;                 // takes a stored study's name (STUDY)
};

// The values an option's CLI::IsMember check accepts, from the check's own description
// ("{a,b,c}"): the list the command line validates against, never a copy of it.
std::vector<std::string> AcceptedValues(CLI::Option& option) {
  for (int i = 0;; ++i) {
    CLI::Validator* check = nullptr;
    try {
      check = option.get_validator(i);
    } catch (const CLI::OptionNotFound&) {
      return {};
    }
    const std::string set = check->get_description();
    if (set.size() < 2 || set.front() != '{' || set.back() != '}') continue;
    std::vector<std::string> values;
    for (std::size_t begin = 1, comma; begin < set.size(); begin = comma + 1) {
      comma = set.find(',', begin);
      if (comma == std::string::npos) comma = set.size() - 1;
      values.push_back(set.substr(begin, comma - begin));
    }
    return values;
  }
}

void Collect(CLI::App& app, const std::string& path, std::vector<CompletionNode>& nodes) {
  CompletionNode node{path, {}, {}, {}, false};
  std::vector<std::pair<CLI::App*, std::string>> children;
  for (CLI::App* sub : app.get_subcommands({})) {
    if (sub->get_group().empty()) continue;  // Hidden.
    node.words.push_back(sub->get_name());
    children.emplace_back(sub, path + " " + sub->get_name());
  }
  for (CLI::Option* option : app.get_options({})) {
    if (!option->nonpositional()) {
      // A study's name (a positional named or typed STUDY), unless the argument is a file
      // (`study run STUDY`).
      const std::string type = option->get_type_name();
      node.study_name = node.study_name || ((option->get_name() == "STUDY" || type == "STUDY") &&
                                            type.find("FILE") == std::string::npos);
      continue;
    }
    const bool takes_value = option->get_expected_max() != 0;
    const std::vector<std::string> choices =
        takes_value ? AcceptedValues(*option) : std::vector<std::string>{};
    const bool folders = option->get_type_name().ends_with(":DIR");
    for (const std::string& name : option->get_lnames()) {
      node.words.push_back("--" + name);
      if (takes_value) node.value_options.push_back("--" + name);
      if (!choices.empty() || folders) node.values.push_back({"--" + name, choices, folders});
    }
  }
  nodes.push_back(std::move(node));
  for (const auto& [sub, sub_path] : children) Collect(*sub, sub_path, nodes);
}

std::string Joined(const std::vector<std::string>& words, const char* separator) {
  std::string s;
  for (const std::string& w : words) s += (s.empty() ? "" : separator) + w;
  return s;
}

// The script's `case` branches: words, options taking a value, value lists, study names.
struct ScriptBranches {
  std::string paths, words, value_options, values, study_names;
};

ScriptBranches Branches(const std::vector<CompletionNode>& nodes) {
  ScriptBranches b;
  for (const CompletionNode& n : nodes) {
    b.paths += fmt::format(" \"{}\"", n.path);
    b.words += fmt::format("    \"{}\") words=\"{}\" ;;\n", n.path, Joined(n.words, " "));
    if (!n.value_options.empty()) {
      b.value_options +=
          fmt::format("    \"{}\") values=\"{}\" ;;\n", n.path, Joined(n.value_options, " "));
    }
    for (const ValueCompletion& v : n.values) {
      b.values +=
          fmt::format("    \"{} {}\") COMPREPLY=($(compgen {} -- \"$cur\")); return ;;\n", n.path,
                      v.option, v.folders ? "-d" : "-W \"" + Joined(v.choices, " ") + "\"");
    }
    if (n.study_name) b.study_names += fmt::format(" \"{}\"", n.path);
  }
  return b;
}

// `completion study-names [--db FILE]`: the stored studies' names, one a line; nothing when the
// database cannot be read (a completion never prints an error).
void AddStudyNamesCommand(CLI::App* completion) {
  CLI::App* names = completion->add_subcommand(
      kStudyNamesCommand, "The stored studies' names, one a line (used by the completion)");
  names->group("");
  auto database_path = std::make_shared<std::string>();
  AddDatabaseFlag(names, *database_path);
  names->callback([database_path] {
    try {
      for (const std::string& name : StudyNames(*database_path)) std::cout << name << '\n';
    } catch (const std::exception&) {
    }
  });
}

}  // namespace

std::string BashCompletion(CLI::App& app) {
  std::vector<CompletionNode> nodes;
  Collect(app, "", nodes);
  const ScriptBranches b = Branches(nodes);
  return fmt::format(
      R"(# bash completion for shockmap, generated by `shockmap completion bash`.
# Install: shockmap completion bash > ~/.local/share/bash-completion/completions/shockmap
_shockmap() {{
  local cur="${{COMP_WORDS[COMP_CWORD]}}" prev="${{COMP_WORDS[COMP_CWORD-1]}}"
  # bash splits "--option=value" at "=".
  if [[ "$cur" == "=" ]]; then
    cur=""
  elif [[ "$prev" == "=" ]]; then
    prev="${{COMP_WORDS[COMP_CWORD-2]}}"
  fi
  local path="" known=({paths}) database=() i candidate node
  for ((i = 1; i < COMP_CWORD; i++)); do
    if [[ "${{COMP_WORDS[i]}}" == "--db" ]] && ((i + 1 < COMP_CWORD)); then
      database=(--db "${{COMP_WORDS[i+1]/#\~/$HOME}}")
    fi
    candidate="$path ${{COMP_WORDS[i]}}"
    for node in "${{known[@]}}"; do
      if [[ "$node" == "$candidate" ]]; then path="$candidate"; break; fi
    done
  done
  # The value of an option: from its list, a folder, else a file name or a number.
  case "$path $prev" in
{values}  esac
  local words="" values=""
  case "$path" in
{value_options}  esac
  if [[ " $values " == *" $prev "* ]]; then
    COMPREPLY=()
    return
  fi
  case "$path" in
{words}  esac
  local node_taking_a_study
  for node_taking_a_study in{study_names}; do
    if [[ "$path" == "$node_taking_a_study" && "$cur" != -* ]]; then
      words="$("${{COMP_WORDS[0]}}" completion {names} "${{database[@]}}" 2>/dev/null) $words"
    fi
  done
  COMPREPLY=($(compgen -W "$words" -- "$cur"))
}}
complete -o default -F _shockmap shockmap
)",
      fmt::arg("paths", b.paths), fmt::arg("values", b.values),
      fmt::arg("value_options", b.value_options), fmt::arg("words", b.words),
      fmt::arg("study_names", b.study_names), fmt::arg("names", kStudyNamesCommand));
}

void AddCompletionCommand(CLI::App& app) {
  CLI::App* completion =
      app.add_subcommand("completion", "Print a shell completion script for shockmap");
  CLI::App* bash = completion->add_subcommand(
      "bash",
      "Bash completion of every command and option (source it, or save it as "
      "~/.local/share/bash-completion/completions/shockmap)");
  bash->callback([&app] { std::cout << BashCompletion(app); });
  AddStudyNamesCommand(completion);
  // A shell not listed is named in the refusal, with the shells there are. Set after the shells
  // are added, which would inherit it: a shell refuses any word or flag after its name.
  completion->require_subcommand(0, 1)->allow_extras();
  completion->callback([completion] {
    if (!completion->get_subcommands().empty()) return;
    const std::vector<std::string> extras = completion->remaining();
    throw InputError(
        "completion: " +
        (extras.empty() ? std::string("name a shell")
                        : "\"" + Excerpt(extras.front()) + "\" is not a shell shockmap completes") +
        "; the shells: bash");
  });
}

}  // namespace shockmap
