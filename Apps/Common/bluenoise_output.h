// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Output of the programs: an output folder written atomically, point writers
// chosen by the file's extension, and a progress bar.
#ifndef bluenoise_output_h
#define bluenoise_output_h

#include <chrono>
#include <string>
#include <utility>
#include <vector>

class vtkAlgorithm;
class vtkObject;
class vtkPolyData;

namespace bluenoise
{
/**
 * An output folder that a failed run leaves as it was. Open() creates the
 * folder when needed and proves it writable (a message with the system's
 * reason otherwise); files are written under temporary names in it
 * (Temporary()), and Commit() renames them all to their names at the end.
 * Without Commit() (a failure, an early return) the destructor removes the
 * temporary files, and the folder when Open() created it.
 */
class OutputFolder
{
public:
  OutputFolder() = default;
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  bool Open(const std::string& folder, std::string& error);
  /// The final path of `name` in the folder.
  std::string Final(const std::string& name) const;
  /// A temporary path to write `name` to; Commit() renames it to Final(name).
  std::string Temporary(const std::string& name);
  bool Commit(std::string& error);

private:
  void Discard();
  std::string Folder;
  std::vector<std::string> Created; // folders Open() made, outermost first
  bool Committed = false;
  std::vector<std::pair<std::string, std::string>> Files; // temporary, final
};

/// The point formats: ".vtp", ".csv" or ".ply" (case-insensitive); false otherwise.
bool IsPointFileName(const std::string& name);
/**
 * Writes the points and their point-data arrays in the format of `path`'s
 * extension: .vtp (VTK XML, compressed inline binary), .csv (x,y,z then one
 * column per array component, a header line), .ply (binary little endian,
 * float x y z and one float property per single-component numeric array).
 * False with `error` (naming the file and the system's reason) on failure.
 */
bool WritePoints(vtkPolyData* points, const std::string& path, const std::string& format,
  std::string& error);

/**
 * A progress bar on stderr for an algorithm's ProgressEvent: shown only when
 * stderr is a terminal and once the run has lasted a second; nothing else is
 * printed. Attach() before Update(); the bar ends with the run (EndEvent).
 */
class ProgressBar
{
public:
  ProgressBar() = default;
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;
  void Attach(vtkAlgorithm* algorithm, const std::string& label);

private:
  static void OnEvent(vtkObject*, unsigned long, void*, void*);
  void Show(double progress);
  void Finish();
  vtkAlgorithm* Algorithm = nullptr;
  unsigned long Tags[3] = { 0, 0, 0 };
  std::string Label;
  std::chrono::steady_clock::time_point Start;
  bool Terminal = false;
  bool Shown = false;
  int LastPercent = -1;
};
}

#endif
