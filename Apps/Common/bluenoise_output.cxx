// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// See bluenoise_output.h.
#include "bluenoise_output.h"

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iostream>
#include <sys/stat.h>
#include <unistd.h>

namespace bluenoise
{
namespace
{
std::string Extension(const std::string& name)
{
  return vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(name));
}

std::string Reason()
{
  return std::strerror(errno);
}

// The numeric point arrays written besides the coordinates.
std::vector<vtkDataArray*> NumericArrays(vtkPolyData* points, bool singleComponent)
{
  std::vector<vtkDataArray*> arrays;
  vtkPointData* pd = points->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (array && array->GetName() && (!singleComponent || array->GetNumberOfComponents() == 1))
    {
      arrays.push_back(array);
    }
  }
  return arrays;
}

bool WriteCSV(vtkPolyData* points, const std::string& path, std::string& error)
{
  std::ofstream out(path);
  if (!out)
  {
    error = "cannot write " + path + ": " + Reason();
    return false;
  }
  const auto arrays = NumericArrays(points, false);
  out << "x,y,z";
  for (vtkDataArray* array : arrays)
  {
    const int n = array->GetNumberOfComponents();
    for (int c = 0; c < n; ++c)
    {
      out << "," << array->GetName() << (n > 1 ? "_" + std::to_string(c) : std::string());
    }
  }
  out << "\n";
  char buffer[32];
  for (vtkIdType i = 0; i < points->GetNumberOfPoints() && out; ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    out << p[0] << "," << p[1] << "," << p[2];
    for (vtkDataArray* array : arrays)
    {
      for (int c = 0; c < array->GetNumberOfComponents(); ++c)
      {
        std::snprintf(buffer, sizeof(buffer), ",%.9g", array->GetComponent(i, c));
        out << buffer;
      }
    }
    out << "\n";
  }
  out.close();
  if (!out)
  {
    error = "cannot write " + path + ": " + Reason();
    return false;
  }
  return true;
}

bool WritePLY(vtkPolyData* points, const std::string& path, std::string& error)
{
  std::ofstream out(path, std::ios::binary);
  if (!out)
  {
    error = "cannot write " + path + ": " + Reason();
    return false;
  }
  const auto arrays = NumericArrays(points, true);
  out << "ply\nformat binary_little_endian 1.0\ncomment bluenoise samples\n"
      << "element vertex " << points->GetNumberOfPoints() << "\n"
      << "property float x\nproperty float y\nproperty float z\n";
  for (vtkDataArray* array : arrays)
  {
    out << "property float " << array->GetName() << "\n";
  }
  out << "end_header\n";
  std::vector<float> row(3 + arrays.size());
  for (vtkIdType i = 0; i < points->GetNumberOfPoints() && out; ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    for (int c = 0; c < 3; ++c)
    {
      row[c] = static_cast<float>(p[c]);
    }
    for (size_t a = 0; a < arrays.size(); ++a)
    {
      row[3 + a] = static_cast<float>(arrays[a]->GetComponent(i, 0));
    }
    // PLY's binary_little_endian: the host order on the platforms VTK builds for here.
    out.write(reinterpret_cast<const char*>(row.data()),
      static_cast<std::streamsize>(row.size() * sizeof(float)));
  }
  out.close();
  if (!out)
  {
    error = "cannot write " + path + ": " + Reason();
    return false;
  }
  return true;
}

bool WriteVTP(vtkPolyData* points, const std::string& path, std::string& error)
{
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(points);
  writer->SetFileName(path.c_str());
  // Inline binary (base64, compressed), not appended: appended data cannot be
  // read by VTK < 9.3.1 with Expat >= 2.6.0, e.g. Debian's ParaView 5.11 (see
  // bluenoise_xml_reader.h), whereas inline data is plain XML every VTK reads.
  writer->SetDataModeToBinary();
  writer->SetCompressorTypeToZLib();
  errno = 0;
  writer->Write();
  // Write() returns 1 even when the file could not be written: the error code tells.
  if (writer->GetErrorCode() != vtkErrorCode::NoError)
  {
    error = "cannot write " + path + ": " +
      (errno ? Reason() : vtkErrorCode::GetStringFromErrorCode(writer->GetErrorCode()));
    return false;
  }
  return true;
}
}

//------------------------------------------------------------------------------
OutputFolder::~OutputFolder()
{
  if (!this->Committed)
  {
    this->Discard();
  }
}

bool OutputFolder::Open(const std::string& folder, std::string& error)
{
  this->Folder = folder;
  std::vector<std::string> missing;
  std::string path = vtksys::SystemTools::CollapseFullPath(folder);
  struct stat info;
  while (stat(path.c_str(), &info) != 0)
  {
    if (errno != ENOENT || path.empty() || path == "/")
    {
      error = "cannot create the output folder " + folder + ": " + Reason();
      return false;
    }
    missing.insert(missing.begin(), path);
    path = vtksys::SystemTools::GetFilenamePath(path);
  }
  if (!S_ISDIR(info.st_mode))
  {
    error = "cannot write to " + folder + ": " + path + " is not a folder";
    return false;
  }
  for (const std::string& dir : missing)
  {
    if (mkdir(dir.c_str(), 0777) != 0)
    {
      error = "cannot create the output folder " + folder + ": " + Reason();
      return false;
    }
    this->Created.push_back(dir);
  }
  // Writable: a probe file, removed at once.
  const std::string probe = this->Temporary("write-probe");
  const int fd = open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0666);
  if (fd < 0)
  {
    error = "cannot write to the output folder " + folder + ": " + Reason();
    this->Files.clear();
    return false;
  }
  close(fd);
  std::remove(probe.c_str());
  this->Files.clear();
  return true;
}

std::string OutputFolder::Final(const std::string& name) const
{
  return this->Folder + "/" + name;
}

std::string OutputFolder::Temporary(const std::string& name)
{
  const std::string temporary =
    this->Folder + "/." + name + ".partial-" + std::to_string(static_cast<long>(getpid()));
  this->Files.emplace_back(temporary, this->Final(name));
  return temporary;
}

bool OutputFolder::Commit(std::string& error)
{
  // What would make a rename fail is checked for every file before the first
  // rename, so that a failure changes nothing.
  for (const auto& file : this->Files)
  {
    struct stat info;
    if (stat(file.second.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
    {
      error = "cannot replace " + file.second + ": " + std::strerror(EISDIR);
      return false;
    }
  }
  for (const auto& file : this->Files)
  {
    if (std::rename(file.first.c_str(), file.second.c_str()) != 0)
    {
      error = "cannot rename " + file.first + " to " + file.second + ": " + Reason();
      return false;
    }
  }
  this->Committed = true;
  return true;
}

void OutputFolder::Discard()
{
  for (const auto& file : this->Files)
  {
    std::remove(file.first.c_str());
  }
  for (auto dir = this->Created.rbegin(); dir != this->Created.rend(); ++dir)
  {
    rmdir(dir->c_str());
  }
}

//------------------------------------------------------------------------------
bool IsPointFileName(const std::string& name)
{
  const std::string e = Extension(name);
  return e == ".vtp" || e == ".csv" || e == ".ply";
}

bool WritePoints(
  vtkPolyData* points, const std::string& path, const std::string& format, std::string& error)
{
  const std::string e = Extension(format);
  if (e == ".csv")
  {
    return WriteCSV(points, path, error);
  }
  if (e == ".ply")
  {
    return WritePLY(points, path, error);
  }
  if (e == ".vtp")
  {
    return WriteVTP(points, path, error);
  }
  error = "unknown point format '" + e + "' (.vtp, .csv or .ply)";
  return false;
}

//------------------------------------------------------------------------------
ProgressBar::~ProgressBar()
{
  if (this->Algorithm)
  {
    for (unsigned long tag : this->Tags)
    {
      this->Algorithm->RemoveObserver(tag);
    }
  }
  this->Finish();
}

void ProgressBar::Attach(vtkAlgorithm* algorithm, const std::string& label)
{
  this->Terminal = isatty(STDERR_FILENO) == 1;
  if (!this->Terminal)
  {
    return;
  }
  this->Algorithm = algorithm;
  this->Label = label;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(&ProgressBar::OnEvent);
  callback->SetClientData(this);
  this->Tags[0] = algorithm->AddObserver(vtkCommand::StartEvent, callback);
  this->Tags[1] = algorithm->AddObserver(vtkCommand::ProgressEvent, callback);
  this->Tags[2] = algorithm->AddObserver(vtkCommand::EndEvent, callback);
}

void ProgressBar::OnEvent(vtkObject*, unsigned long event, void* clientData, void* callData)
{
  auto* self = static_cast<ProgressBar*>(clientData);
  if (event == vtkCommand::StartEvent)
  {
    self->Start = std::chrono::steady_clock::now();
  }
  else if (event == vtkCommand::ProgressEvent && callData)
  {
    self->Show(*static_cast<double*>(callData));
  }
  else if (event == vtkCommand::EndEvent)
  {
    self->Finish();
  }
}

void ProgressBar::Show(double progress)
{
  const int percent = static_cast<int>(progress * 100.0);
  if (percent == this->LastPercent ||
    std::chrono::steady_clock::now() - this->Start < std::chrono::seconds(1))
  {
    return;
  }
  this->LastPercent = percent;
  this->Shown = true;
  const int width = 40;
  const int filled = std::max(0, std::min(width, percent * width / 100));
  std::cerr << "\r" << this->Label << " [" << std::string(filled, '#')
            << std::string(width - filled, ' ') << "] " << percent << "%" << std::flush;
}

void ProgressBar::Finish()
{
  if (this->Shown)
  {
    std::cerr << "\n" << std::flush;
    this->Shown = false;
  }
  this->LastPercent = -1;
}
}
