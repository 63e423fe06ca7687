package masl.maven;

import java.io.IOException;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.diagnostic.Diagnostic;
import masl.runtime.diagnostic.DiagnosticPrinter;
import masl.translator.Translation;
import masl.translator.Translator;
import masl.translator.source.SourceFile;
import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;

/**
 * Translates every program of a project's {@code src/main/masl} or {@code src/test/masl}, as
 * {@code masl check} and {@code masl compile} do: each program against the descriptors next to it,
 * along the agent path and on the class path, and each descriptor against its agent class, with the
 * project's own Java of that half compiled first ({@link AgentClasses}). Every program's errors are reported in one failure, with masl's
 * {@code file:line:column} diagnostics.
 */
final class ProjectTranslation {

    private final ProgramsMojo mojo;
    private final SourceScope scope;

    ProjectTranslation(ProgramsMojo mojo, SourceScope scope) {
        this.mojo = mojo;
        this.scope = scope;
    }

    /**
     * The generated Java of every program, by class name.
     *
     * @throws MojoFailureException naming each error of the programs, their descriptors or the project's Java
     */
    Map<String, String> translate(List<Path> programs) throws MojoExecutionException, MojoFailureException {
        Path agentClasses = scope.agentClasses(mojo.project());
        List<Path> classPath = scope.classPath(mojo.project());
        AgentClasses.compile(scope.javaSourceRoots(mojo.project()).stream().map(Path::of).toList(), classPath, agentClasses,
                sourceEncoding());
        List<Path> lookup = new ArrayList<>(List.of(agentClasses));
        lookup.addAll(classPath);
        Map<String, String> texts = new LinkedHashMap<>();
        List<Diagnostic> errors = new ArrayList<>();
        Map<String, String> javaSources = new LinkedHashMap<>();
        try (URLClassLoader classes = new URLClassLoader(urls(lookup), ProjectTranslation.class.getClassLoader())) {
            Translator translator = new Translator(AgentPath.of(mojo.agentPath(), classes));
            for (Path program : programs) {
                SourceFile source = read(program);
                texts.put(source.name(), source.text());
                Translation translation = translator.translate(source);
                if (translation.succeeded()) {
                    javaSources.putAll(translation.javaSources());
                } else {
                    errors.addAll(translation.diagnostics().sorted());
                }
            }
        } catch (IOException cannotClose) {
            throw new MojoExecutionException("cannot close the class loader of the agent classes", cannotClose);
        }
        if (!errors.isEmpty()) {
            throw new MojoFailureException("MASL translation failed:\n" + new DiagnosticPrinter(texts).report(errors));
        }
        return javaSources;
    }

    private String sourceEncoding() {
        String encoding = mojo.project().getProperties().getProperty("project.build.sourceEncoding");
        return encoding == null || encoding.isBlank() ? "UTF-8" : encoding;
    }

    /** The program, named relative to the project as a user would type it in a shell there. */
    private SourceFile read(Path program) throws MojoFailureException {
        try {
            SourceFile absolute = SourceFile.read(program);
            return new SourceFile(mojo.relative(program), absolute.folder(), absolute.text());
        } catch (IOException unreadable) {
            throw new MojoFailureException(mojo.relative(program) + ": cannot be read (" + unreadable.getMessage() + ")");
        }
    }

    private static URL[] urls(List<Path> entries) throws MojoExecutionException {
        List<URL> urls = new ArrayList<>();
        for (Path entry : entries) {
            try {
                urls.add(entry.toUri().toURL());
            } catch (MalformedURLException notALocation) {
                throw new MojoExecutionException(entry + " is not a class path entry", notALocation);
            }
        }
        return urls.toArray(URL[]::new);
    }
}
