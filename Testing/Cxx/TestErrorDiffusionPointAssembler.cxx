// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkErrorDiffusionPointAssembler: layers held back (Hold), trimmed at their
// end (DropLast, across layers) and written later, by hand side by side
// (Write without the other arrays, in any order, then WriteOthers) or by
// WriteHeld (on this thread, and spread over the threads where the layers
// hold enough points), give the same points and arrays as the same layers
// added at once (AddLayer, then RemoveLast). Random masks and densities; rows
// not a multiple of eight voxels; numeric, bit and string arrays. Then a
// store large enough for the assembler's blocks, held, released and held
// again.
#include "BlueNoiseTestUtilities.h"
#include "vtkBitArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorDiffusionPointAssembler.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include <random>
#include <vector>

using namespace bluenoise_test;

namespace
{
using Assembler = vtkErrorDiffusionPointAssembler;

// How HoldThenWrite writes the held layers.
enum class Writing
{
  ByHand,    // Write side by side in reverse order, then WriteOthers
  Held,      // WriteHeld on this thread
  HeldSpread // WriteHeld, on the threads when there are enough points
};

struct Layers
{
  std::vector<std::vector<float>> Density;
  std::vector<std::vector<unsigned char>> Mask;
  std::vector<vtkIdType> Count;
};

vtkSmartPointer<vtkImageData> MakeImage(int nx, int ny, int nz, std::mt19937& random)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, nz);
  image->SetOrigin(1.0, -2.0, 0.5);
  image->SetSpacing(0.5, 2.0, 1.5);
  const vtkIdType n = image->GetNumberOfPoints();
  vtkNew<vtkDoubleArray> vectors;
  vectors->SetName("vectors");
  vectors->SetNumberOfComponents(3);
  vectors->SetNumberOfTuples(n);
  vtkNew<vtkBitArray> bits;
  bits->SetName("bits");
  bits->SetNumberOfTuples(n);
  vtkNew<vtkStringArray> names;
  names->SetName("names");
  names->SetNumberOfTuples(n);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    vectors->SetTuple3(i, uniform(random), uniform(random), static_cast<double>(i));
    bits->SetValue(i, static_cast<int>(random() & 1));
    names->SetValue(i, "v" + Str(i));
  }
  image->GetPointData()->AddArray(vectors);
  image->GetPointData()->AddArray(bits);
  image->GetPointData()->AddArray(names);
  return image;
}

Layers MakeLayers(int nx, int ny, int nz, double fill, std::mt19937& random)
{
  Layers layers;
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (int z = 0; z < nz; ++z)
  {
    std::vector<float> density(static_cast<size_t>(nx) * ny);
    std::vector<unsigned char> mask(density.size());
    vtkIdType count = 0;
    for (size_t i = 0; i < density.size(); ++i)
    {
      density[i] = uniform(random);
      mask[i] = uniform(random) < fill ? 1 : 0;
      count += mask[i];
    }
    layers.Density.push_back(density);
    layers.Mask.push_back(mask);
    layers.Count.push_back(count);
  }
  return layers;
}

// The points of all layers through AddLayer, the last `drop` removed.
vtkSmartPointer<vtkPolyData> AddAtOnce(vtkImageData* image, const Layers& layers, vtkIdType drop)
{
  auto output = vtkSmartPointer<vtkPolyData>::New();
  Assembler assembler;
  assembler.Begin(image, image->GetExtent(), output->GetPointData(), VTK_FLOAT);
  for (size_t z = 0; z < layers.Mask.size(); ++z)
  {
    assembler.AddLayer(static_cast<int>(z), layers.Density[z].data(), layers.Mask[z].data(),
      layers.Count[z]);
  }
  assembler.RemoveLast(drop);
  output->SetPoints(assembler.End());
  return output;
}

// The first `direct` layers through AddLayer, the others held, `drop`
// dropped from them, then written as `writing` says.
vtkSmartPointer<vtkPolyData> HoldThenWrite(
  vtkImageData* image, const Layers& layers, size_t direct, vtkIdType drop, Writing writing)
{
  auto output = vtkSmartPointer<vtkPolyData>::New();
  Assembler assembler;
  assembler.Begin(image, image->GetExtent(), output->GetPointData(), VTK_FLOAT);
  Assembler::HeldLayers held;
  vtkIdType expected = 0;
  for (size_t z = 0; z < layers.Mask.size(); ++z)
  {
    const int k = static_cast<int>(z);
    if (z < direct)
    {
      assembler.AddLayer(k, layers.Density[z].data(), layers.Mask[z].data(), layers.Count[z]);
      continue;
    }
    assembler.Hold(k, layers.Density[z].data(), layers.Mask[z].data(), held);
    expected += layers.Count[z];
  }
  Check(held.GetNumberOfPoints() == expected,
    "held " + Str(held.GetNumberOfPoints()) + " points, not " + Str(expected));
  Check(held.DropLast(drop) == drop, "DropLast dropped fewer than asked");
  const vtkIdType first = assembler.Grow(held.GetNumberOfPoints());
  if (writing != Writing::ByHand)
  {
    assembler.WriteHeld(held, first, writing == Writing::HeldSpread);
    held.Release();
    output->SetPoints(assembler.End());
    return output;
  }
  std::vector<vtkIdType> starts;
  vtkIdType at = first;
  for (size_t l = 0; l < held.GetNumberOfLayers(); ++l)
  {
    starts.push_back(at);
    at += held.GetLayer(l).Count();
  }
  Check(at == assembler.GetNumberOfPoints(), "the held layers do not fill the room grown");
  for (size_t l = held.GetNumberOfLayers(); l-- > 0;)
  {
    assembler.Write(held.GetLayer(l), starts[l], false);
  }
  for (size_t l = 0; l < held.GetNumberOfLayers(); ++l)
  {
    assembler.WriteOthers(held.GetLayer(l), starts[l]);
  }
  held.Release();
  output->SetPoints(assembler.End());
  return output;
}

void Compare(vtkPolyData* a, vtkPolyData* b, const std::string& what)
{
  const vtkIdType n = a->GetNumberOfPoints();
  if (!Check(n == b->GetNumberOfPoints(),
        what + ": " + Str(b->GetNumberOfPoints()) + " points, not " + Str(n)))
  {
    return;
  }
  vtkIdType different = 0;
  for (vtkIdType p = 0; p < n; ++p)
  {
    double x[3], y[3];
    a->GetPoint(p, x);
    b->GetPoint(p, y);
    different += (x[0] != y[0] || x[1] != y[1] || x[2] != y[2]) ? 1 : 0;
  }
  Check(different == 0, what + ": " + Str(different) + " points differ");
  for (const char* name : { "vectors", "bits", "names", "Density" })
  {
    vtkAbstractArray* u = a->GetPointData()->GetAbstractArray(name);
    vtkAbstractArray* v = b->GetPointData()->GetAbstractArray(name);
    if (!Check(u && v && u->GetNumberOfTuples() == n && v->GetNumberOfTuples() == n,
          what + ": array " + name + " missing or of another length"))
    {
      continue;
    }
    vtkIdType values = 0;
    for (vtkIdType i = 0; i < n * u->GetNumberOfComponents(); ++i)
    {
      values += u->GetVariantValue(i) == v->GetVariantValue(i) ? 0 : 1;
    }
    Check(values == 0, what + ": " + Str(values) + " values of " + name + " differ");
  }
}
} // namespace

int main()
{
  std::mt19937 random(7);
  const int nx = 37, ny = 5, nz = 6;
  auto image = MakeImage(nx, ny, nz, random);
  for (const double fill : { 0.05, 0.5, 0.95 })
  {
    const Layers layers = MakeLayers(nx, ny, nz, fill, random);
    // Nothing dropped, part of the last layer, the last layer and more.
    for (const vtkIdType drop : { vtkIdType(0), vtkIdType(1), layers.Count[nz - 1] + 3 })
    {
      for (const size_t direct : { size_t(0), size_t(2) })
      {
        for (const Writing writing : { Writing::ByHand, Writing::Held })
        {
          Compare(AddAtOnce(image, layers, drop),
            HoldThenWrite(image, layers, direct, drop, writing),
            "fill " + Str(fill) + ", " + Str(direct) + " layers direct, " + Str(drop) +
              " dropped, writing " + Str(static_cast<int>(writing)));
        }
      }
    }
  }

  // Enough held points for WriteHeld to spread them over the threads.
  {
    const int side = 512, layersHeld = 4;
    auto large = MakeImage(side, side - 3, layersHeld + 1, random);
    const Layers layers = MakeLayers(side, side - 3, layersHeld + 1, 0.5, random);
    Compare(AddAtOnce(large, layers, 5), HoldThenWrite(large, layers, 1, 5, Writing::HeldSpread),
      "large, spread over the threads");
  }

  // A store in blocks (tens of MB), released and held again; Clear keeps it.
  {
    const int side = 1024;
    auto big = vtkSmartPointer<vtkImageData>::New();
    big->SetDimensions(side, side, 2);
    const Layers layers = MakeLayers(side, side, 2, 0.5, random);
    vtkNew<vtkPolyData> output;
    Assembler assembler;
    assembler.Begin(big, big->GetExtent(), output->GetPointData(), VTK_FLOAT);
    Assembler::HeldLayers held;
    for (int round = 0; round < 3; ++round)
    {
      held.SetRoom(vtkIdType(2) * side * side);
      for (int z = 0; z < 2; ++z)
      {
        assembler.Hold(z, layers.Density[z].data(), layers.Mask[z].data(), held);
      }
      const auto last = held.GetLayer(1);
      const vtkIdType id = last.Ids[last.Count() - 1];
      Check(held.GetNumberOfPoints() == layers.Count[0] + layers.Count[1] &&
          last.Densities[last.Count() - 1] == layers.Density[1][static_cast<size_t>(id)] &&
          layers.Mask[1][static_cast<size_t>(id)] == 1,
        "round " + Str(round) + ": the large store's samples are not the masks'");
      if (round == 1)
      {
        held.Clear();
        Check(held.GetNumberOfPoints() == 0 && held.GetNumberOfLayers() == 0, "Clear kept layers");
      }
      held.Release();
    }
    assembler.End();
  }
  return Summary("TestErrorDiffusionPointAssembler");
}
