bluenoise_add_benchmark(BenchmarkErrorDiffusionSampler)
# The real-volume case reads Debian's ch2bet.nii.gz.
target_link_libraries(BenchmarkErrorDiffusionSampler PRIVATE VTK::IOImage VTK::vtksys)
