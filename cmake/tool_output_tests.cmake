# The tools' output tests: those that run a tool on good input and check what it writes against
# the library's results. They carry the ctest label `tool_output`, which the check's sanitize
# stage leaves out (tools/check): the library code they reach runs under the sanitizers in the
# library's own tests, and the tools' code runs there through the hostile-input suite
# (tests/hostile_input), whose cases start every tool on good input up to a write that fails and
# on bad input.
set(EDGEWISE_TOOL_OUTPUT_LABEL tool_output)

# edgewise_label_tool_output_tests(): labels every test added so far in the calling directory
# (gtest_discover_tests' tests take `PROPERTIES LABELS ${EDGEWISE_TOOL_OUTPUT_LABEL}` instead).
function(edgewise_label_tool_output_tests)
  get_directory_property(tests TESTS)
  if(tests)
    set_tests_properties(${tests} PROPERTIES LABELS ${EDGEWISE_TOOL_OUTPUT_LABEL})
  endif()
endfunction()
