// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The z-parts the scanning methods sample side by side (PartLayers,
// PartVoxels): the output does not depend on the threads (nor on whether a
// part has a worker thread beside it), the slabs or the chunks a part is
// scanned in; the count stays exact (within max(2,
// 0.05 %)); the 16 layers around each seam hold their expected count within
// 2 %; the mask matches the points and the attributes their voxels (numeric
// and string arrays); the paper's method and both relaxed ones; progress
// goes from 0 to 1 and never back; an abort between chunks leaves an empty
// output.
#include "SamplerTestUtilities.h"
#include "vtkBlueNoiseSpectrum.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkTable.h"

#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

using namespace bluenoise_test;

namespace
{
constexpr int NX = 64, NY = 48, NZ = 320, PartLayers = 32; // 10 parts

float Density(int i, int j, int k)
{
  return 0.02f + 0.12f * (0.5f + 0.5f * std::sin(k / 23.0f)) * (i + j) / float(NX + NY);
}

// The mean anisotropy (dB, below half the grid's frequencies) and L(g) of the
// points of a constant cube of edge n, on the cube's own grid.
void Spectrum(vtkPolyData* points, int n, double& anisotropy, double& low)
{
  vtkNew<vtkBlueNoiseSpectrum> spectrum;
  spectrum->SetUseInputGrid(false);
  spectrum->SetGridDimensions(n, n, n);
  spectrum->UseGridBoundsOn();
  spectrum->SetGridBounds(0, n - 1, 0, n - 1, 0, n - 1);
  spectrum->SetInputData(points);
  spectrum->Update();
  vtkTable* table = spectrum->GetOutput();
  vtkDataArray* column = vtkDataArray::SafeDownCast(table->GetColumnByName("AnisotropyDB"));
  anisotropy = 0.0;
  for (int f = 0; f < n / 2; ++f)
  {
    anisotropy += column->GetTuple1(f) / (n / 2);
  }
  low = table->GetFieldData()->GetArray("LowFrequencyRatio")->GetTuple1(0);
}

class ProgressRecorder : public vtkCommand
{
public:
  static ProgressRecorder* New() { return new ProgressRecorder; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    this->Values.push_back(*static_cast<double*>(data));
  }
  std::vector<double> Values;
};

class AbortObserver : public vtkCommand
{
public:
  static AbortObserver* New() { return new AbortObserver; }
  void Execute(vtkObject* caller, unsigned long, void* data) override
  {
    if (*static_cast<double*>(data) >= 0.3)
    {
      bluenoise_test::Abort(static_cast<vtkAlgorithm*>(caller));
    }
  }
};
}

int main()
{
  auto image = MakeVolume(NX, NY, NZ, Density);
  std::vector<double> layerSums(NZ, 0.0);
  for (int k = 0; k < NZ; ++k)
  {
    for (int j = 0; j < NY; ++j)
    {
      for (int i = 0; i < NX; ++i)
      {
        layerSums[k] += Density(i, j, k);
      }
    }
  }
  double expected = 0.0;
  for (double sum : layerSums)
  {
    expected += sum;
  }
  // On `image`, or on `volume` whose values are densities / `scale`.
  const auto run = [&](int threads, int slabs, int partLayers, int method,
                     vtkImageData* volume = nullptr, double scale = 1.0) {
    vtkSmartPointer<vtkPolyData> points;
    WithThreads(threads, [&] {
      points = Sample(volume ? volume : image.Get(), [&](vtkErrorDiffusionSampler* s) {
        s->SetMethod(method);
        s->SetDensityScale(scale);
        s->SetPartLayers(partLayers);
        s->SetPartVoxels(65536);
        s->SetNumberOfSlabs(slabs);
        s->SetSeed(7);
      });
    });
    return points;
  };

  // The error-diffusion methods: the paper's, the default (relaxed), whose
  // relaxation runs in each part, and the energy relaxed one, whose two
  // passes do.
  const int ed = vtkErrorDiffusionSampler::METHOD_ERROR_DIFFUSION;
  const int relaxed = vtkErrorDiffusionSampler::METHOD_RELAXED_ERROR_DIFFUSION;
  const int energy = vtkErrorDiffusionSampler::METHOD_ENERGY_RELAXED_ERROR_DIFFUSION;
  const auto nameOf = [&](int method) {
    return std::string(method == ed ? "paper's" : method == energy ? "energy" : "default") +
      " method";
  };
  // The runs on several threads first (see WithThreads).
  // Twice as many threads as parts: each part with a worker thread beside it.
  const int paired = 2 * NZ / PartLayers;
  std::map<int, std::array<vtkSmartPointer<vtkPolyData>, 4>> several;
  for (const int method : { relaxed, energy, ed })
  {
    several[method] = { run(4, 1, PartLayers, method), run(3, 7, PartLayers, method),
      run(4, 1, 65536, method), run(paired, 1, PartLayers, method) };
  }
  vtkSmartPointer<vtkPolyData> one; // the paper's method's, last: the checks below compare with it
  for (const int method : { relaxed, energy, ed })
  {
    const std::string name = nameOf(method) + ": ";
    one = run(1, 1, PartLayers, method);
    const auto& [four, streamed, whole, pairs] = several[method];
    Check(SamePoints(one, four), name + "1 and 4 threads: the same points (" +
        Str(one->GetNumberOfPoints()) + ", " + Str(four->GetNumberOfPoints()) + ")");
    Check(SamePoints(one, pairs), name + "1 and " + Str(paired) +
        " threads (a worker thread beside each part): the same points");
    Check(SamePoints(one, streamed), name + "in 7 slabs: the same points as in one go");
    Check(!SamePoints(one, whole), name + "10 parts sample otherwise than one part");
    const double n = static_cast<double>(one->GetNumberOfPoints());
    Check(std::abs(n - expected) <= std::max(2.0, 0.0005 * expected),
      name + "10 parts: " + Str(one->GetNumberOfPoints()) + " points, expected " + Str(expected));

    // The 16 layers around each seam.
    std::vector<vtkIdType> perLayer(NZ, 0);
    for (vtkIdType p = 0; p < one->GetNumberOfPoints(); ++p)
    {
      ++perLayer[static_cast<size_t>(std::lround(one->GetPoint(p)[2]))];
    }
    for (int seam = PartLayers; seam < NZ; seam += PartLayers)
    {
      double got = 0.0, want = 0.0;
      for (int k = seam - 8; k < seam + 8; ++k)
      {
        got += perLayer[k];
        want += layerSums[k];
      }
      Check(std::abs(got / want - 1.0) <= 0.02,
        name + "seam at z = " + Str(seam) + ": " + Str(got) + " points, expected " + Str(want));
    }
  }

  // The seams cost little blue noise: on a constant cube of 96^3 in parts of
  // 32 layers, the whole set's L(g) within 2 % and its mean anisotropy within
  // 0.5 dB of one part's, each averaged over 2 seeds. The energy relaxed
  // method's within 5 %: it takes L(g) well below the default's,
  // but near a seam its passes see the other part's layers as scanned (below)
  // or not at all (above), and lose more of it there.
  {
    const int n = 96;
    auto cube = MakeVolume(n, n, n, [](int, int, int) { return 8.0f / 255.0f; });
    for (const int method : { relaxed, ed, energy })
    {
      const std::string name = nameOf(method) + ": ";
      double figures[2][2] = { { 0.0, 0.0 }, { 0.0, 0.0 } }; // [parts][anisotropy, L]
      for (int parts = 0; parts < 2; ++parts)
      {
        for (int seed = 1; seed <= 2; ++seed)
        {
          auto points = Sample(cube, [&](vtkErrorDiffusionSampler* s) {
            s->SetMethod(method);
            s->SetPartLayers(parts ? 32 : 65536);
            s->SetPartVoxels(65536);
            s->SetSeed(seed);
          });
          double anisotropy = 0.0, low = 0.0;
          Spectrum(points, n, anisotropy, low);
          figures[parts][0] += anisotropy / 2;
          figures[parts][1] += low / 2;
        }
      }
      std::cout << name << "mean anisotropy " << figures[1][0] << " dB in 3 parts, "
                << figures[0][0] << " dB in one; L " << figures[1][1] << ", " << figures[0][1]
                << "\n";
      Check(std::abs(figures[1][0] - figures[0][0]) <= 0.5,
        name + "3 parts: mean anisotropy " + Str(figures[1][0]) + " dB, one part " +
          Str(figures[0][0]) + " dB");
      Check(std::abs(figures[1][1] / figures[0][1] - 1.0) <= (method == energy ? 0.05 : 0.02),
        name + "3 parts: L " + Str(figures[1][1]) + ", one part " + Str(figures[0][1]));
    }
  }

  // A sampler of the error-diffusion method in parts, not run yet.
  const auto inParts = [&]() {
    auto sampler = vtkSmartPointer<vtkErrorDiffusionSampler>::New();
    sampler->SetInputData(image);
    sampler->SetDensityMappingToIdentity();
    sampler->UseNumberOfPointsOff();
    sampler->SetMethod(ed);
    sampler->SetPartLayers(PartLayers);
    sampler->SetPartVoxels(65536);
    sampler->SetSeed(7);
    return sampler;
  };

  // The mask of a run in parts marks the points' voxels.
  {
    auto sampler = inParts();
    sampler->GenerateMaskOn();
    sampler->Update();
    vtkDataArray* mask = sampler->GetMaskOutput()->GetPointData()->GetScalars();
    vtkPolyData* points = sampler->GetOutput();
    bool marked = mask != nullptr;
    vtkIdType ones = 0;
    for (vtkIdType v = 0; marked && v < mask->GetNumberOfTuples(); ++v)
    {
      ones += mask->GetTuple1(v) != 0.0;
    }
    for (vtkIdType p = 0; marked && p < points->GetNumberOfPoints(); ++p)
    {
      const double* x = points->GetPoint(p);
      const vtkIdType v = (std::lround(x[2]) * NY + std::lround(x[1])) * NX + std::lround(x[0]);
      marked = mask->GetTuple1(v) != 0.0;
    }
    Check(marked && ones == points->GetNumberOfPoints() && SamePoints(points, one),
      "the mask marks the " + Str(points->GetNumberOfPoints()) + " points (" + Str(ones) +
        " ones) and the points are those without a mask");
  }

  // A part scans its overlap in place of a warm-up, which makes up only what
  // the overlap is short of: with the overlap (8) as long as the warm-up,
  // WarmUpLayers changes the first part's points alone; with a shorter one,
  // the other parts' too.
  {
    // The points of layers below the first seam (0) or from it on (1).
    const auto warmed = [&](int warmUp, int overlap, int side) {
      auto sampler = inParts();
      sampler->SetWarmUpLayers(warmUp);
      sampler->SetOverlapLayers(overlap);
      sampler->Update();
      std::vector<double> coordinates;
      vtkPolyData* points = sampler->GetOutput();
      for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
      {
        const double* x = points->GetPoint(p);
        if ((std::lround(x[2]) >= PartLayers) == (side == 1))
        {
          coordinates.insert(coordinates.end(), x, x + 3);
        }
      }
      return coordinates;
    };
    Check(warmed(8, 8, 0) != warmed(4, 8, 0), "the warm-up changes the first part's points");
    Check(warmed(8, 8, 1) == warmed(4, 8, 1),
      "an overlap as long as the warm-up: the other parts' points do not depend on it");
    Check(warmed(8, 2, 1) != warmed(4, 2, 1),
      "an overlap shorter than the warm-up: the other parts' points depend on it");
  }

  // The attributes in parts: a numeric and a string array carried from the
  // voxels, each naming the point's layer.
  {
    auto labelled = MakeVolume(NX, NY, NZ, Density);
    vtkNew<vtkIntArray> layers;
    layers->SetName("layer");
    vtkNew<vtkStringArray> names;
    names->SetName("name");
    layers->SetNumberOfValues(labelled->GetNumberOfPoints());
    names->SetNumberOfValues(labelled->GetNumberOfPoints());
    for (vtkIdType v = 0; v < labelled->GetNumberOfPoints(); ++v)
    {
      const int k = static_cast<int>(v / (NX * NY));
      layers->SetValue(v, k);
      names->SetValue(v, "z" + std::to_string(k));
    }
    labelled->GetPointData()->AddArray(layers);
    labelled->GetPointData()->AddArray(names);
    auto points = run(4, 1, PartLayers, vtkErrorDiffusionSampler::METHOD_ERROR_DIFFUSION, labelled);
    auto* layer = vtkIntArray::SafeDownCast(points->GetPointData()->GetArray("layer"));
    auto* name = vtkStringArray::SafeDownCast(points->GetPointData()->GetAbstractArray("name"));
    bool carried = layer && name && SamePoints(points, one);
    for (vtkIdType p = 0; carried && p < points->GetNumberOfPoints(); ++p)
    {
      const int k = static_cast<int>(std::lround(points->GetPoint(p)[2]));
      carried = layer->GetValue(p) == k && name->GetValue(p) == "z" + std::to_string(k);
    }
    Check(carried, "in parts, every point carries its own voxel's numeric and string values");
  }

  // 8-bit values in parts side by side: each part maps its layers through a
  // table of densities of its own, made by its first layer (one shared table
  // was a data race: now and then a crash, or a part's counts in another's
  // layer sums). Fresh filters, so that the tables are made each time.
  {
    auto bytes = vtkSmartPointer<vtkImageData>::New();
    bytes->CopyStructure(image);
    vtkNew<vtkUnsignedCharArray> values;
    values->SetName("values");
    values->SetNumberOfValues(image->GetNumberOfPoints());
    double sum = 0.0;
    for (vtkIdType v = 0; v < values->GetNumberOfValues(); ++v)
    {
      const double g = image->GetPointData()->GetScalars()->GetTuple1(v);
      values->SetValue(v, static_cast<unsigned char>(std::lround(255.0 * g)));
      sum += values->GetValue(v) / 255.0;
    }
    bytes->GetPointData()->SetScalars(values);
    const auto sample = [&](int threads) {
      return run(threads, 1, PartLayers, ed, bytes, 1.0 / 255.0);
    };
    const auto expectedOf = [](vtkPolyData* points) {
      vtkDataArray* e = points->GetFieldData()->GetArray("ExpectedNumberOfPoints");
      return e ? e->GetTuple1(0) : -1.0;
    };
    auto single = sample(1);
    const double n = static_cast<double>(single->GetNumberOfPoints());
    Check(std::abs(n - sum) <= std::max(2.0, 0.0005 * sum) &&
        std::abs(expectedOf(single) - sum) <= 1e-6 * sum,
      "8-bit values in parts: " + Str(n) + " points, expected " + Str(expectedOf(single)) +
        ", the sum of the densities " + Str(sum));
    for (int run = 0; run < 3; ++run)
    {
      auto four = sample(4);
      Check(SamePoints(four, single) && expectedOf(four) == expectedOf(single),
        "8-bit values in parts, 4 threads (run " + Str(run) +
          "): the points and the expected count of one thread");
    }
  }

  // Parts scanned a chunk at a time: at 2^19 voxels a layer a chunk is two
  // layers, so each part of six (and its overlap) is scanned in several
  // calls of its runner, the kernel's, the relaxation's and the held
  // layers' state carried from one to the next; one thread scans each part
  // in one call.
  {
    constexpr int CX = 1024, CY = 512, CZ = 24;
    auto wide = MakeVolume(CX, CY, CZ, [](int i, int j, int k) {
      return 0.01f + 0.1f * (0.5f + 0.5f * std::sin(k / 3.0f)) * (i + j) / float(CX + CY);
    });
    for (const int method : { relaxed, ed, energy })
    {
      const auto sample = [&](int threads) { return run(threads, 1, 6, method, wide); };
      auto chunked = sample(3);
      auto single = sample(1);
      Check(single->GetNumberOfPoints() > 100000 && SamePoints(chunked, single),
        nameOf(method) + ", parts of several chunks: the same points on 3 threads as on 1 (" +
          Str(chunked->GetNumberOfPoints()) + ", " + Str(single->GetNumberOfPoints()) + ")");
    }
  }

  // White noise in parts: the same whatever the threads.
  const int white = vtkErrorDiffusionSampler::METHOD_WHITE_NOISE;
  Check(SamePoints(run(1, 1, PartLayers, white), run(4, 3, PartLayers, white)),
    "white noise in parts: the same points with 1 and 4 threads, in one go and in 3 slabs");

  // Progress from 0 to 1 and never back, on one thread (the parts one after
  // another) and on four (the parts side by side, then the last one alone),
  // in one slab and in seven.
  for (const int threads : { 1, 4 })
  {
    for (const int slabs : { 1, 7 })
    {
      auto sampler = inParts();
      sampler->SetNumberOfSlabs(slabs);
      vtkNew<ProgressRecorder> progress;
      sampler->AddObserver(vtkCommand::ProgressEvent, progress);
      WithThreads(threads, [&] { sampler->Update(); });
      const auto& v = progress->Values;
      bool increasing = !v.empty() && v.front() == 0.0 && v.back() == 1.0;
      for (size_t i = 1; i < v.size(); ++i)
      {
        increasing = increasing && v[i] >= v[i - 1];
      }
      // One thread scans each part at once and reports layer by layer; parts
      // side by side report between epochs (this volume takes one).
      Check(increasing && (threads > 1 || v.size() >= 100),
        "progress in parts goes from 0 to 1 and never back (" + Str(threads) + " threads, " +
          Str(slabs) + " slabs, " + Str(v.size()) + " reports)");
    }
  }

  // The parts a caller asks about before an execution are those it plans:
  // by layers (10 here), by voxels (with PartVoxels of 8 layers' worth, 4
  // by layers; with one of 5 layers' worth and more, 2), and one for the
  // whole-volume methods. The product of layers and voxels may exceed what
  // vtkIdType holds.
  {
    auto sampler = inParts();
    const int planned = sampler->GetNumberOfPartsFor(NZ, NX * NY);
    sampler->Update();
    Check(planned == 10 && sampler->GetNumberOfParts() == planned,
      "parts planned and parts made: " + Str(planned) + ", " + Str(sampler->GetNumberOfParts()));
    sampler->SetPartVoxels(vtkIdType(80) * NX * NY);
    Check(sampler->GetNumberOfPartsFor(NZ, NX * NY) == 4, "parts by PartVoxels");
    sampler->SetPartLayers(150);
    sampler->SetPartVoxels(vtkIdType(5) * NX * NY);
    Check(sampler->GetNumberOfPartsFor(NZ, NX * NY) == 2, "parts by PartLayers");
    sampler->SetPartVoxels(vtkIdType(1) << 62);
    sampler->SetPartLayers(2);
    Check(sampler->GetNumberOfPartsFor(vtkIdType(1) << 33, vtkIdType(1) << 33) == 16,
      "parts of a volume of more voxels than vtkIdType holds");
    sampler->SetMethod(vtkErrorDiffusionSampler::METHOD_POISSON_DISK);
    Check(sampler->GetNumberOfPartsFor(NZ, NX * NY) == 1 &&
        sampler->GetNumberOfPartsFor(0, NX * NY) == 1,
      "one part for a whole-volume method and for no layers");
  }

  // An abort between chunks: an empty output, and the next update samples.
  {
    auto sampler = inParts();
    vtkNew<AbortObserver> abort;
    const unsigned long tag = sampler->AddObserver(vtkCommand::ProgressEvent, abort);
    sampler->Update();
    Check(sampler->GetOutput()->GetNumberOfPoints() == 0, "aborted in parts: an empty output");
    sampler->RemoveObserver(tag);
    sampler->SetAbortExecute(0);
    sampler->Modified();
    sampler->Update();
    Check(SamePoints(sampler->GetOutput(), one), "after the abort, the same points as before");
  }
  return Summary("TestErrorDiffusionSamplerParts");
}
