// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// See bluenoise_sampler_choices.h.
#include "bluenoise_sampler_choices.h"

#include "vtkErrorDiffusionSampler.h"
#include "vtkNew.h"

#include <algorithm>

namespace bluenoise
{
namespace
{
using Sampler = vtkErrorDiffusionSampler;

// The choices with the one whose value is `first` moved to the front.
std::vector<SamplerChoice> DefaultFirst(std::vector<SamplerChoice> choices, int first)
{
  std::stable_partition(choices.begin(), choices.end(),
    [first](const SamplerChoice& c) { return c.Value == first; });
  return choices;
}

const char* NameOf(const std::vector<SamplerChoice>& choices, int value)
{
  for (const auto& c : choices)
  {
    if (c.Value == value)
    {
      return c.Name;
    }
  }
  return "custom";
}
}

std::vector<SamplerChoice> SamplerMethods()
{
  vtkNew<Sampler> defaults;
  return DefaultFirst(
    {
      { "relaxed-error-diffusion", Sampler::METHOD_RELAXED_ERROR_DIFFUSION,
        "relaxed error diffusion" },
      { "energy-relaxed-error-diffusion", Sampler::METHOD_ENERGY_RELAXED_ERROR_DIFFUSION,
        "energy relaxed error diffusion" },
      { "error-diffusion", Sampler::METHOD_ERROR_DIFFUSION, "error diffusion" },
      { "white-noise", Sampler::METHOD_WHITE_NOISE, "white noise" },
      { "poisson-disk", Sampler::METHOD_POISSON_DISK, "Poisson disk" },
      { "sample-elimination", Sampler::METHOD_SAMPLE_ELIMINATION, "sample elimination" },
    },
    defaults->GetMethod());
}

std::vector<SamplerChoice> SamplerParameterSets()
{
  vtkNew<Sampler> defaults;
  return DefaultFirst(
    {
      { "optimized", Sampler::PARAMETERS_OPTIMIZED, "optimized parameters" },
      { "paper", Sampler::PARAMETERS_PAPER, "paper (Table 1) parameters" },
      { "fixed", Sampler::PARAMETERS_FIXED, "fixed parameters" },
    },
    defaults->GetParameterSet());
}

std::string DefaultMethodName()
{
  vtkNew<Sampler> defaults;
  return NameOf(SamplerMethods(), defaults->GetMethod());
}

std::string DefaultParameterSetName()
{
  vtkNew<Sampler> defaults;
  return NameOf(SamplerParameterSets(), defaults->GetParameterSet());
}

std::string ChoiceNames(const std::vector<SamplerChoice>& choices)
{
  std::string names;
  for (size_t i = 0; i < choices.size(); ++i)
  {
    names += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ");
    names += choices[i].Name;
  }
  return names;
}

bool FindChoice(
  const std::vector<SamplerChoice>& choices, const std::string& name, SamplerChoice& found)
{
  auto choice = std::find_if(choices.begin(), choices.end(),
    [&name](const SamplerChoice& c) { return name == c.Name; });
  if (choice == choices.end())
  {
    return false;
  }
  found = *choice;
  return true;
}
}
