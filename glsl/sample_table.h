// sample_table.h — the constants that glsl/sample_table.glsl and the C++
// runner share: the table's layout (runner/sampling/sample_table_generator.h
// SampleTable::kColumns, kSets), which the runner generates and uploads.
// Valid as GLSL and as C++: only comments and guarded #defines.

#ifndef PENUMBRA_SAMPLE_TABLE_H
#define PENUMBRA_SAMPLE_TABLE_H

// Columns: the 1-, 4- and 16-sample groups side by side (1 + 4 + 16); rows:
// independent sets (a power of two: the set is (x + y) & (sets - 1)).
#ifndef PN_SAMPLE_TABLE_COLUMNS
#define PN_SAMPLE_TABLE_COLUMNS 21
#endif
#ifndef PN_SAMPLE_TABLE_SETS
#define PN_SAMPLE_TABLE_SETS 8
#endif

#endif  // PENUMBRA_SAMPLE_TABLE_H
