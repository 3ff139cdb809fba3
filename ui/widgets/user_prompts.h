// What the workbench asks the user through a dialog — a file to open, where
// to write, a folder — and the pages it hands to the desktop (the manual),
// as replaceable functions: a test answers them without a modal dialog
// waiting for a click.
#pragma once

#include <QDesktopServices>
#include <QFileDialog>
#include <QString>
#include <QUrl>
#include <QWidget>

#include <functional>

namespace drape {

struct UserPrompts {
  using AskFile = std::function<QString(QWidget*, const QString& caption, const QString& filter)>;
  AskFile open_file = [](QWidget* parent, const QString& caption, const QString& filter) {
    return QFileDialog::getOpenFileName(parent, caption, {}, filter);
  };
  AskFile save_file = [](QWidget* parent, const QString& caption, const QString& filter) {
    return QFileDialog::getSaveFileName(parent, caption, {}, filter);
  };
  std::function<QString(QWidget*, const QString& caption)> directory = [](QWidget* parent,
                                                                          const QString& caption) {
    return QFileDialog::getExistingDirectory(parent, caption);
  };
  std::function<bool(const QUrl&)> open_url = [](const QUrl& url) {
    return QDesktopServices::openUrl(url);
  };
};

}  // namespace drape
