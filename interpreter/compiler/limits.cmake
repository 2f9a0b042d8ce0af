# Nesting limits and what keeps recursion bounded: the AST's copy and destruction without
# recursion, and the thread the compiler runs on (limits.h).
target_sources(iec_interpreter PRIVATE
  compiler/limits.h
  compiler/ast.cpp
  compiler/compilerstack.h
  compiler/compilerstack.cpp
)
