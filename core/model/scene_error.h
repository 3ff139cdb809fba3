// The one error a user sees for a bad scene: where (a JSON path such as
// `stages[2].moves[0].path.arc.axis`, or a line and column) and what is wrong.
#pragma once

#include <stdexcept>
#include <string>

namespace drape {

class SceneError : public std::runtime_error {
 public:
  // `where` is a JSON path or "line L, column C"; empty means the whole file.
  SceneError(std::string where, std::string message)
      : std::runtime_error(where.empty() ? message : where + ": " + message),
        where_(std::move(where)),
        message_(std::move(message)) {}

  const std::string& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  std::string where_;
  std::string message_;
};

}  // namespace drape
