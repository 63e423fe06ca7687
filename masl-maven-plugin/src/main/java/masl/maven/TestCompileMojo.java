package masl.maven;

/**
 * {@code masl:testCompile}, in {@code generate-test-sources}: {@code masl:compile} for the missions the
 * tests use, those of {@code src/test/masl}, into {@code target/generated-test-sources/masl}, a test
 * source root. They are checked against their descriptors, these against the agent classes of
 * {@code src/test/java} and, on the test class path, of the main code already compiled (its
 * descriptors among its resources); a mistake in a test's mission fails the build at its
 * {@code file:line:column} before any test runs, as one in the main code's does.
 */
public class TestCompileMojo extends CompileMojo {

    @Override
    SourceScope scope() {
        return SourceScope.TEST;
    }
}
