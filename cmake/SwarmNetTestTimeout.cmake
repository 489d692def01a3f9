# swarmnet_test_timeout(<seconds> <test>...): the tests' time limit, in seconds on the normal build.
# Under the sanitizers (SWARMNET_SANITIZE, SWARMNET_TSAN) the same code runs about five times
# slower (far_signals_identical: about 30 s, 168-176 s under ASan+UBSan), so those builds stretch
# every explicit limit alike. Tests without one get ctest's --timeout from ./swarmnet.
function(swarmnet_test_timeout seconds)
  set(scale 1)
  if(SWARMNET_SANITIZE OR SWARMNET_TSAN)
    set(scale 5)
  endif()
  math(EXPR limit "${seconds} * ${scale}")
  set_tests_properties(${ARGN} PROPERTIES TIMEOUT ${limit})
endfunction()
