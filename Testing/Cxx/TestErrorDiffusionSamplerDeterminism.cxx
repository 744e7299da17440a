// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Same seed: the same points bit for bit; another seed: other points; the scan
// on a worker thread or not: the same output. Density g and 1 - g with the same
// seed: complementary masks (the mirrored process). 16-bit values: the points
// of the same values as floats. A re-execution writes a large output into
// the last output's memory, or, when a shallow copy held that output (as
// ParaView's post filter does), into that memory once the copy lets it go.
// A filter re-executed after other settings gives a fresh filter's points.
#include "SamplerTestUtilities.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnsignedShortArray.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h> // mincore
#include <unistd.h>   // sysconf
#endif

using namespace bluenoise_test;

namespace
{
std::string Exact(double x)
{
  std::ostringstream out;
  out << std::setprecision(17) << x;
  return out.str();
}

// The paper's error diffusion (the relaxation of the default method moves
// samples of g <= 1/4 only, so g and 1 - g would not mirror each other).
vtkSmartPointer<vtkImageData> MaskOf(vtkImageData* image, int seed)
{
  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputData(image);
  sampler->SetMethodToErrorDiffusion();
  sampler->SetDensityMappingToIdentity();
  sampler->UseNumberOfPointsOff();
  sampler->SetSeed(seed);
  sampler->GenerateMaskOn();
  sampler->Update();
  auto mask = vtkSmartPointer<vtkImageData>::New();
  mask->DeepCopy(sampler->GetMaskOutput());
  return mask;
}

// Outputs of 8 MB and more live in memory blocks of their own (on Linux): a
// re-execution writes into the last output's block, a smaller output keeps
// the block, a larger one after it is right again, and an array a downstream
// user grows keeps its values.
#if defined(__linux__) && defined(MADV_FREE)
// Whether the pages of [data, data + bytes) are mapped.
bool Mapped(const void* data, size_t bytes)
{
  const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(data) / page * page;
  std::vector<unsigned char> resident(bytes / page + 2);
  return mincore(reinterpret_cast<void*>(begin), bytes, resident.data()) == 0;
}

// ParaView keeps a shallow copy of every output until the filter after it
// runs again (vtkPVPostFilter): a re-execution cannot write into the last
// output, which is freed just after it. That memory should stay, for the
// next execution to write into instead of faulting in fresh pages.
void CheckHeldOutputReuse(vtkErrorDiffusionSampler* sampler, vtkPolyData* expected)
{
  vtkNew<vtkPolyData> postFilter;
  postFilter->ShallowCopy(sampler->GetOutput());
  const void* first = sampler->GetOutput()->GetPoints()->GetData()->GetVoidPointer(0);
  const size_t bytes = static_cast<size_t>(expected->GetNumberOfPoints()) * 3 * sizeof(float);
  sampler->Modified();
  sampler->Update(); // the first output is held: fresh memory
  postFilter->ShallowCopy(sampler->GetOutput()); // and now freed
  Check(Mapped(first, bytes), "a freed output's memory stays mapped");
  sampler->Modified();
  sampler->Update();
  Check(SamePoints(sampler->GetOutput(), expected) &&
      sampler->GetOutput()->GetPoints()->GetData()->GetVoidPointer(0) == first,
    "the execution after a held output writes into that output's memory once it is freed");
}
#else
void CheckHeldOutputReuse(vtkErrorDiffusionSampler*, vtkPolyData*) {}
#endif

void CheckLargeOutputReuse()
{
  const int n = 160; // about 2 M points at g = 1/2: 24 MB of coordinates
  auto volume = MakeVolume(n, n, n, [](int, int, int) { return 0.5f; });
  const auto configure = [&](vtkErrorDiffusionSampler* s, double scale) {
    s->SetInputData(volume);
    s->SetMethodToErrorDiffusion();
    s->SetDensityMappingToIdentity();
    s->UseNumberOfPointsOff();
    s->SetDensityScale(scale);
  };
  const auto fresh = [&](double scale) {
    vtkNew<vtkErrorDiffusionSampler> s;
    configure(s, scale);
    s->Update();
    return vtkSmartPointer<vtkPolyData>(s->GetOutput());
  };
  const auto full = fresh(1.0);
  const auto tenth = fresh(0.1);
  vtkNew<vtkErrorDiffusionSampler> sampler;
  configure(sampler, 1.0);
  sampler->Update();
  const void* block = sampler->GetOutput()->GetPoints()->GetData()->GetVoidPointer(0);
  sampler->Modified();
  sampler->Update();
  Check(SamePoints(sampler->GetOutput(), full) &&
      sampler->GetOutput()->GetPoints()->GetData()->GetVoidPointer(0) == block,
    "a re-execution writes the large points into the last output's memory");
  sampler->SetDensityScale(0.1);
  sampler->Update();
  Check(SamePoints(sampler->GetOutput(), tenth) &&
      sampler->GetOutput()->GetPoints()->GetNumberOfPoints() < full->GetNumberOfPoints() / 5,
    "a smaller output in the same memory");
  sampler->SetDensityScale(1.0);
  sampler->Update();
  Check(SamePoints(sampler->GetOutput(), full), "a larger output after it: the same points");
  CheckHeldOutputReuse(sampler, full);
  vtkNew<vtkPolyData> held;
  held->ShallowCopy(sampler->GetOutput());
  vtkDataArray* density = held->GetPointData()->GetArray("Density");
  const vtkIdType count = density->GetNumberOfTuples();
  const double first = density->GetTuple1(0);
  const double last = density->GetTuple1(count - 1);
  density->InsertNextTuple1(2.0); // VTK reallocates: a copy out of the block
  Check(density->GetNumberOfTuples() == count + 1 && density->GetTuple1(0) == first &&
      density->GetTuple1(count - 1) == last && density->GetTuple1(count) == 2.0,
    "an output array grown downstream keeps its values");
}
}

int main()
{
  CheckLargeOutputReuse();
  // A non-constant volume so the interpolated parameters are exercised too.
  auto image = MakeVolume(40, 36, 32, [](int i, int j, int k) {
    return 0.05f + 0.3f * static_cast<float>((i * 7 + j * 3 + k * 5) % 17) / 16.0f;
  });
  auto seeded = [](int seed) { return [seed](vtkErrorDiffusionSampler* s) { s->SetSeed(seed); }; };
  auto a = Sample(image, seeded(7));
  auto b = Sample(image, seeded(7));
  auto c = Sample(image, seeded(8));
  Check(a->GetNumberOfPoints() > 1000, "enough samples: " + Str(a->GetNumberOfPoints()));
  Check(SamePoints(a, b), "same seed gives the same points");
  Check(!SamePoints(a, c), "another seed gives other points");

  // The worker thread changes who does the work, not the result: points and
  // every point array the same, on a volume with empty and full voxels.
  {
    auto holes = MakeVolume(48, 40, 36, [](int i, int j, int k) {
      const int v = (i * 7 + j * 3 + k * 5) % 23;
      return v < 3 ? 0.0f : (v > 20 ? 1.0f : 0.02f * static_cast<float>(v));
    });
    auto threaded = Sample(holes, [](vtkErrorDiffusionSampler* s) { s->SetUseWorkerThread(true); });
    auto single = Sample(holes, [](vtkErrorDiffusionSampler* s) { s->SetUseWorkerThread(false); });
    bool sameArrays = threaded->GetPointData()->GetNumberOfArrays() ==
      single->GetPointData()->GetNumberOfArrays();
    for (int a = 0; sameArrays && a < threaded->GetPointData()->GetNumberOfArrays(); ++a)
    {
      vtkDataArray* x = threaded->GetPointData()->GetArray(a);
      vtkDataArray* y = single->GetPointData()->GetArray(x->GetName());
      sameArrays = y && x->GetNumberOfValues() == y->GetNumberOfValues() &&
        x->GetDataTypeSize() == y->GetDataTypeSize() &&
        std::memcmp(x->GetVoidPointer(0), y->GetVoidPointer(0),
          static_cast<size_t>(x->GetNumberOfValues()) * x->GetDataTypeSize()) == 0;
    }
    Check(threaded->GetNumberOfPoints() > 1000 && SamePoints(threaded, single) && sameArrays &&
        threaded->GetNumberOfVerts() == threaded->GetNumberOfPoints(),
      "worker thread and single thread give the same output (" + Str(threaded->GetNumberOfPoints()) +
        " and " + Str(single->GetNumberOfPoints()) + " points)");
  }

  // Re-executing the same filter after a seed change follows the seed.
  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputData(image);
  sampler->SetSeed(7);
  sampler->SetDensityMappingToIdentity();
  sampler->UseNumberOfPointsOff();
  sampler->Update();
  auto first = vtkSmartPointer<vtkPolyData>::New();
  first->DeepCopy(sampler->GetOutput());
  sampler->SetSeed(8);
  sampler->Update();
  Check(SamePoints(sampler->GetOutput(), c), "seed change re-executes");
  sampler->SetSeed(7);
  sampler->Update();
  Check(SamePoints(sampler->GetOutput(), first), "seed restored gives the first points again");
  // The filter keeps its kernel (and the charge curves it used) from run to
  // run: after runs with another table, scale and method, a fresh filter's
  // points.
  sampler->SetParameterSet(vtkErrorDiffusionSampler::PARAMETERS_PAPER);
  sampler->SetModulationScale(0.75);
  sampler->SetMethodToErrorDiffusion();
  sampler->Update();
  sampler->SetMethodToWhiteNoise();
  sampler->Update();
  sampler->SetParameterSet(vtkErrorDiffusionSampler::PARAMETERS_OPTIMIZED);
  sampler->SetModulationScale(0.5);
  sampler->SetMethodToRelaxedErrorDiffusion();
  sampler->Update();
  Check(SamePoints(sampler->GetOutput(), first),
    "after runs with other tables, scales and methods: the first points again");

  // A re-execution writes into the last output's arrays when nothing else
  // holds them (the same array objects), and leaves alone what another
  // object holds: a shallow copy keeps its points.
  {
    // (Deleted arrays are counted: a new array could get an old one's address.)
    int deleted = 0;
    vtkNew<vtkCallbackCommand> onDelete;
    onDelete->SetCallback([](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
    onDelete->SetClientData(&deleted);
    vtkDataArray* before = sampler->GetOutput()->GetPoints()->GetData();
    vtkDataArray* densityBefore = sampler->GetOutput()->GetPointData()->GetArray("Density");
    before->AddObserver(vtkCommand::DeleteEvent, onDelete);
    densityBefore->AddObserver(vtkCommand::DeleteEvent, onDelete);
    sampler->SetSeed(8);
    sampler->Update();
    Check(deleted == 0 && sampler->GetOutput()->GetPoints()->GetData() == before &&
        sampler->GetOutput()->GetPointData()->GetArray("Density") == densityBefore &&
        SamePoints(sampler->GetOutput(), c),
      "a re-execution reuses the arrays nothing else holds, with the right points (" +
        Str(deleted) + " deleted)");
    if (deleted == 0)
    {
      before->RemoveObservers(vtkCommand::DeleteEvent);
      densityBefore->RemoveObservers(vtkCommand::DeleteEvent);
    }
    // The reused Density array's range follows its new values.
    double before2[2];
    sampler->GetOutput()->GetPointData()->GetArray("Density")->GetRange(before2);
    sampler->SetDensityScale(0.5);
    sampler->Update();
    vtkDataArray* halved = sampler->GetOutput()->GetPointData()->GetArray("Density");
    double range[2];
    halved->GetRange(range);
    double direct[2] = { 1e30, -1e30 };
    for (vtkIdType i = 0; i < halved->GetNumberOfTuples(); ++i)
    {
      direct[0] = std::min(direct[0], halved->GetTuple1(i));
      direct[1] = std::max(direct[1], halved->GetTuple1(i));
    }
    Check(range[0] == direct[0] && range[1] == direct[1] && range[1] < before2[1],
      "a reused array's range is that of its new values: " + Str(range[0]) + " " + Str(range[1]) +
        " (before " + Str(before2[1]) + ")");
    sampler->SetDensityScale(1.0);
    sampler->SetSeed(8);
    sampler->Update();
    vtkNew<vtkPolyData> held;
    held->ShallowCopy(sampler->GetOutput());
    sampler->SetSeed(7);
    sampler->Update();
    Check(SamePoints(held, c) && SamePoints(sampler->GetOutput(), first) &&
        sampler->GetOutput()->GetPoints()->GetData() != held->GetPoints()->GetData(),
      "a shallow copy of the last output keeps its points through a re-execution");
  }

  // 16-bit values on layers of 512^2 go through a table of densities kept
  // from layer to layer: the same points as the same values in floats, and a
  // table rebuilt when the scale changes on the same filter.
  {
    auto asFloat = MakeVolume(512, 512, 3, [](int i, int j, int k) {
      return static_cast<float>((i * 131 + j * 71 + k * 17) % 9000);
    });
    auto asShort = vtkSmartPointer<vtkImageData>::New();
    asShort->CopyStructure(asFloat);
    vtkNew<vtkUnsignedShortArray> values;
    values->SetName("values");
    values->SetNumberOfValues(asFloat->GetNumberOfPoints());
    for (vtkIdType i = 0; i < values->GetNumberOfValues(); ++i)
    {
      values->SetValue(i, static_cast<unsigned short>(asFloat->GetPointData()->GetScalars()->GetTuple1(i)));
    }
    asShort->GetPointData()->SetScalars(values);
    auto scaled = [](double scale) {
      return [scale](vtkErrorDiffusionSampler* s) {
        s->SetDensityMappingToScalarRange();
        s->SetDensityScale(scale);
      };
    };
    auto reference = Sample(asFloat, scaled(0.1));
    vtkNew<vtkErrorDiffusionSampler> reused;
    reused->SetInputData(asShort);
    scaled(0.3)(reused);
    reused->UseNumberOfPointsOff();
    reused->Update();
    scaled(0.1)(reused);
    reused->Update();
    Check(reference->GetNumberOfPoints() > 1000 && SamePoints(reused->GetOutput(), reference),
      "16-bit values through the table give the points of the same values as floats, after a "
      "change of scale (" + Str(reused->GetOutput()->GetNumberOfPoints()) + " and " +
        Str(reference->GetNumberOfPoints()) + " points)");
  }

  // The point budget's scale is a function of the values alone: not of the
  // threads the statistics pass splits them over, nor of the slabs they come
  // in (doubles of full precision, whose sums in another order round
  // differently; 2^20 voxels, so that the pass splits).
  {
    auto varied = vtkSmartPointer<vtkImageData>::New();
    varied->SetDimensions(128, 128, 64);
    vtkNew<vtkDoubleArray> values;
    values->SetName("values");
    values->SetNumberOfValues(varied->GetNumberOfPoints());
    std::mt19937_64 random(5);
    for (vtkIdType i = 0; i < values->GetNumberOfValues(); ++i)
    {
      values->SetValue(i, std::uniform_real_distribution<double>(0.0, 0.5)(random));
    }
    varied->GetPointData()->SetScalars(values);
    const auto scaleOf = [&](int threads, int slabs) {
      vtkSmartPointer<vtkPolyData> points;
      WithThreads(threads, [&] {
        points = Sample(varied, [slabs](vtkErrorDiffusionSampler* s) {
          s->UseNumberOfPointsOn();
          s->SetNumberOfPoints(30000);
          s->SetNumberOfSlabs(slabs);
        });
      });
      return points->GetFieldData()->GetArray("DensityScale")->GetTuple1(0);
    };
    // Two threads first (see WithThreads).
    const double two = scaleOf(2, 1);
    const double streamed = scaleOf(2, 7);
    const double one = scaleOf(1, 1);
    Check(one > 0.0 && one == two && one == streamed,
      "the budget's scale with 1 and 2 threads and 7 slabs: " + Exact(one) + ", " + Exact(two) +
        ", " + Exact(streamed));
  }

  // Complement: density g and 1 - g, same seed.
  const int L = 32;
  auto low = MakeVolume(L, L, L, [](int i, int, int k) { return 0.03f + 0.01f * ((i + k) % 5); });
  auto high = MakeVolume(L, L, L, [](int i, int, int k) { return 1.0f - (0.03f + 0.01f * ((i + k) % 5)); });
  auto mLow = MaskOf(low, 3);
  auto mHigh = MaskOf(high, 3);
  auto* bl = mLow->GetPointData()->GetScalars();
  auto* bh = mHigh->GetPointData()->GetScalars();
  vtkIdType agree = 0;
  const vtkIdType voxels = bl->GetNumberOfTuples();
  for (vtkIdType i = 0; i < voxels; ++i)
  {
    agree += (bl->GetComponent(i, 0) + bh->GetComponent(i, 0) == 1.0) ? 1 : 0;
  }
  // Float rounding of 1 - g may flip a tie now and then; nothing more.
  Check(agree >= voxels - voxels / 1000,
    "g and 1 - g give complementary masks: " + Str(voxels - agree) + " of " + Str(voxels) +
      " voxels differ");
  return Summary("TestErrorDiffusionSamplerDeterminism");
}
