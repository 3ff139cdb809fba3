// Starting `drape run` processes from a command that runs many (study,
// plan): this program's own path, a child with its output in a log, shell
// quoting for job files, and a duration in words.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace drape {

// This program, to start the runs with. A rebuild or reinstall while a
// study goes on replaces the file: Linux then names the old one
// "… (deleted)", and the runs start the new one at the same path.
std::filesystem::path SelfExecutable();

// Starts `args` (args[0] the program) with stdout and stderr in `log`;
// returns its pid, or −1 when it cannot start.
pid_t Spawn(const std::vector<std::string>& args, const std::filesystem::path& log);

// 'text' for a POSIX shell.
std::string ShellQuoted(const std::string& text);

// "4.2 s", "35 s", "12 min", "2.5 h".
std::string Duration(double seconds);

}  // namespace drape
