package masl.translator.analysis;

/**
 * What a name or a member in an expression stands for. The analysis records one for every name
 * ({@code x}, {@code k1}, {@code go}, {@code Math}) and every member access ({@code .getProximity},
 * {@code e.count}, {@code s.substring}) it resolved; see {@link AnalyzedProgram#symbolOf}.
 */
public sealed interface Symbol permits AgentDecl, Variable, EventDecl, Label, EntryRef, TypeRef, Member {
}
