package masl.runtime.descriptor;

import static masl.runtime.descriptor.TestDescriptors.FIXTURE_ROOT;
import static masl.runtime.descriptor.TestDescriptors.write;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.io.OutputStream;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.stream.Stream;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Lookup along the agent path: program folder, entries in order, shipped resources; users' compiled types. */
class AgentPathTest {

    private static final String ARM_SOURCE = """
            package users;

            public class Arm extends masl.runtime.descriptor.fixtures.Default {
                public int reach;

                public void grip(double force) {
                }
            }
            """;

    private static final String ARM_DESCRIPTOR = """
            <?xml version="1.0"?>
            <Agent short_class_name="Arm" full_class_name="users.Arm">
              <Attribute attribute_name="reach" member_id="U1" attribute_class="int.class"/>
              <Primitive function_name="grip" member_id="U2" synchronous_call="false" return_type_name="void">
                <Parameter parameter_name="force" parameter_type="double.class"/>
              </Primitive>
            </Agent>
            """;

    @TempDir
    Path folder;

    @Test
    void parseSplitsOnThePathSeparatorAndSkipsEmptyElements() {
        String separator = File.pathSeparator;
        AgentPath path = AgentPath.parse("robots" + separator + "lib/arm.jar" + separator + separator + "more");
        assertEquals(List.of(Path.of("robots"), Path.of("lib/arm.jar"), Path.of("more")), path.entries());
        assertTrue(AgentPath.parse("").entries().isEmpty());
    }

    @Test
    void lookupOrderIsProgramFolderThenEntriesThenResources() throws IOException {
        Path program = folder.resolve("program");
        Path first = folder.resolve("first");
        Path jar = folder.resolve("second.jar");
        Path third = folder.resolve("third");
        Path shipped = folder.resolve("shipped");
        for (Path dir : List.of(program, first, third, shipped)) {
            write(dir, "X.xml", "<x/>");
        }
        writeJar(jar, "X.xml", "<x/>");
        try (URLClassLoader resources = new URLClassLoader(new URL[] {shipped.toUri().toURL()}, null)) {
            AgentPath path = AgentPath.of(List.of(first, jar, folder.resolve("absent"), third), resources);

            List<String> found = path.findAll("X.xml", program).stream().map(DescriptorSource::displayName).toList();
            assertEquals(List.of(program.resolve("X.xml").toString(), first.resolve("X.xml").toString(),
                    jar + "!/X.xml", third.resolve("X.xml").toString(), "classpath:X.xml"), found);
            assertEquals(program.resolve("X.xml").toString(), path.find("X.xml", program).orElseThrow().displayName());
            assertEquals(first.resolve("X.xml").toString(), path.find("X.xml", null).orElseThrow().displayName());

            Files.delete(first.resolve("X.xml"));
            assertEquals(jar + "!/X.xml", path.find("X.xml", null).orElseThrow().displayName());
            assertTrue(path.find("Y.xml", program).isEmpty());
        }
    }

    @Test
    void shippedDescriptorIsFoundAsAResourceAndAUsersOwnOverridesIt() throws IOException {
        Path shipped = folder.resolve("shipped");
        Files.createDirectories(shipped);
        Files.copy(TestDescriptors.fixtureFolder().resolve("Default.xml"), shipped.resolve("Default.xml"));
        Path user = write(folder.resolve("user"), "Default.xml", """
                <Agent short_class_name="MyDefault" full_class_name="masl.runtime.descriptor.fixtures.Default"/>
                """);
        try (URLClassLoader resources = new URLClassLoader(new URL[] {shipped.toUri().toURL()},
                getClass().getClassLoader())) {
            AgentType fromResources = new DescriptorLoader(AgentPath.of(List.of(), resources), FIXTURE_ROOT)
                    .loadByClassName(FIXTURE_ROOT);
            assertEquals("classpath:Default.xml", fromResources.source().displayName());
            assertEquals(5, fromResources.primitives().size());

            AgentType overridden = new DescriptorLoader(AgentPath.of(List.of(user.getParent()), resources),
                    FIXTURE_ROOT).loadByClassName(FIXTURE_ROOT);
            assertEquals("MyDefault", overridden.shortName());
        }
    }

    @Test
    void usersCompiledTypeInAFolder() throws IOException, ClassNotFoundException {
        Path robots = compileArm(folder.resolve("robots"));
        write(robots, "Arm.xml", ARM_DESCRIPTOR);
        DescriptorLoader loader = TestDescriptors.loader(robots);
        AgentType arm = loader.load(loader.agentPath().find("Arm.xml", null).orElseThrow());
        assertEquals("double", arm.findPrimitive("grip").orElseThrow().parameters().get(0).type());
        assertEquals(FIXTURE_ROOT, arm.superFullClassName());
        assertEquals("users.Arm", Class.forName("users.Arm", false, loader.implementationClasses()).getName());
    }

    @Test
    void usersCompiledTypeInAJarFoundByClassName() throws IOException {
        Path classes = compileArm(folder.resolve("classes"));
        write(classes, "descriptors/ArmV2.xml", ARM_DESCRIPTOR);
        Path jar = folder.resolve("arm.jar");
        jarFolder(classes, jar);
        DescriptorLoader loader = TestDescriptors.loader(jar);
        AgentType arm = loader.loadByClassName("users.Arm");
        assertEquals(jar + "!/descriptors/ArmV2.xml", arm.source().displayName(), "found by scanning the jar");
        assertTrue(arm.findAttribute("reach").isPresent());
        assertSame(arm, loader.loadByClassName("users.Arm"));
    }

    @Test
    void supertypeIsFoundNextToTheSubtypeUnderAnyName() {
        write(folder, "base-arm.xml", """
                <Agent short_class_name="Base" full_class_name="masl.runtime.descriptor.fixtures.Robot"/>
                """);
        Path sub = write(folder, "Sub.xml", """
                <Agent short_class_name="Sub" full_class_name="masl.runtime.descriptor.fixtures.Khepera"
                       super_full_class_name="masl.runtime.descriptor.fixtures.Robot"/>
                """);
        assertEquals("Base", TestDescriptors.loader().load(sub).supertype().shortName());
    }

    @Test
    void classNameWithoutDescriptor() {
        DescriptorException error = assertThrows(DescriptorException.class,
                () -> TestDescriptors.loader().loadByClassName("org.example.Nothing"));
        assertEquals(1, error.problems().size());
        assertTrue(error.problems().get(0).message()
                .contains("no descriptor with full_class_name=\"org.example.Nothing\""), error.getMessage());
    }

    /** Compiles {@link #ARM_SOURCE} against the test class path into {@code output}. */
    private static Path compileArm(Path output) throws IOException {
        Path source = write(output.resolveSibling(output.getFileName() + "-src"), "users/Arm.java", ARM_SOURCE);
        JavaCompiler compiler = ToolProvider.getSystemJavaCompiler();
        int status = compiler.run(null, null, null, "-d", output.toString(), "-classpath",
                System.getProperty("java.class.path"), source.toString());
        assertEquals(0, status, "compiling the user's type failed");
        return output;
    }

    private static void writeJar(Path jar, String entryName, String content) throws IOException {
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar))) {
            out.putNextEntry(new JarEntry(entryName));
            out.write(content.getBytes(java.nio.charset.StandardCharsets.UTF_8));
            out.closeEntry();
        }
    }

    private static void jarFolder(Path folder, Path jar) throws IOException {
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar));
                Stream<Path> files = Files.walk(folder)) {
            for (Path file : files.filter(Files::isRegularFile).sorted().toList()) {
                out.putNextEntry(new JarEntry(folder.relativize(file).toString().replace(File.separatorChar, '/')));
                Files.copy(file, (OutputStream) out);
                out.closeEntry();
            }
        }
    }
}
