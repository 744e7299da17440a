// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The choices of vtkErrorDiffusionSampler the programs offer, by the names
// they take on the command line, and the class's own defaults.
//
// The names are the enum names of the class in lower case with hyphens
// (METHOD_RELAXED_ERROR_DIFFUSION: relaxed-error-diffusion, PARAMETERS_PAPER:
// paper), the choices of the ParaView panel (Method, Parameter Set). The
// defaults are read from a default-constructed sampler, so that the programs,
// the panel (whose XML defaults a test holds to the class's), pvpython and
// C++ have one source of truth.
#ifndef bluenoise_sampler_choices_h
#define bluenoise_sampler_choices_h

#include <string>
#include <vector>

namespace bluenoise
{
struct SamplerChoice
{
  const char* Name;  ///< on the command line, in metrics.csv
  int Value;         ///< the vtkErrorDiffusionSampler enum
  const char* Label; ///< in words, for titles and --help
};

/// vtkErrorDiffusionSampler::Methods, the class's default first.
std::vector<SamplerChoice> SamplerMethods();

/// The named parameter sets (ParameterSet but PARAMETERS_CUSTOM, which is a
/// file), the class's default first.
std::vector<SamplerChoice> SamplerParameterSets();

/// The command-line names of the defaults of a default-constructed sampler.
std::string DefaultMethodName();
std::string DefaultParameterSetName();

/// "a, b or c": the names of `choices`, for messages.
std::string ChoiceNames(const std::vector<SamplerChoice>& choices);

/// The choice named `name` into `found`; false when there is none.
bool FindChoice(
  const std::vector<SamplerChoice>& choices, const std::string& name, SamplerChoice& found);
}

#endif
