package masl.jade.stub;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.OutputStream;
import java.lang.reflect.Constructor;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.net.URI;
import java.net.URISyntaxException;
import java.security.CodeSource;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import javax.tools.DiagnosticCollector;
import javax.tools.FileObject;
import javax.tools.ForwardingJavaFileManager;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileManager;
import javax.tools.JavaFileObject;
import javax.tools.SimpleJavaFileObject;
import javax.tools.ToolProvider;
import masl.jade.platform.JadeException;
import masl.runtime.AgentImplementation;

/**
 * Makes stubs: instances of a subclass of an agent's implementation class whose primitives hand
 * their index and arguments to a {@link BodyStub} (source: {@link StubSource}). The runtime and the
 * generated program call a stub exactly as the implementation ({@code self.logln(…)}, or inside
 * {@code ctx.invoke(…)}), so a program cannot tell where its agent's body is.
 *
 * <p>The stub's source is compiled in memory with {@code javax.tools} (masl runs on a JDK: it
 * compiles the programs it translates), once per implementation class and list of primitives,
 * against the folders and jars the implementation, its superclasses, its primitives' types and
 * this module were loaded from. The implementation class and its primitives' methods must be public
 * and not final, with a public no-argument constructor. Thread-safe.
 *
 * <p>Public for the two kinds of stub: a placed agent's ({@code placement}) and an external agent's
 * ({@code external}).
 */
public final class StubClasses {

    private final Map<StubSource, Constructor<?>> made = new HashMap<>();

    /**
     * A stub of {@code implementation} forwarding {@code methods} (by their index in the list) to
     * {@code stub}. Methods of the class that are not in the list run as the class has them.
     *
     * @throws JadeException if the class or one of the methods cannot be overridden
     */
    public AgentImplementation instantiate(Class<? extends AgentImplementation> implementation, List<Method> methods,
            BodyStub stub) {
        check(implementation, methods);
        try {
            return (AgentImplementation) constructor(new StubSource(implementation, methods)).newInstance(stub);
        } catch (ReflectiveOperationException | LinkageError e) {
            throw new JadeException("cannot make a stub of " + implementation.getName() + ": " + e, e);
        }
    }

    private synchronized Constructor<?> constructor(StubSource source) throws ReflectiveOperationException {
        Constructor<?> constructor = made.get(source);
        if (constructor == null) {
            constructor = compile(source).getConstructor(BodyStub.class);
            made.put(source, constructor);
        }
        return constructor;
    }

    private static void check(Class<?> implementation, List<Method> methods) {
        if (!Modifier.isPublic(implementation.getModifiers()) || Modifier.isFinal(implementation.getModifiers())) {
            throw new JadeException(implementation.getName() + " must be public and not final to be placed in"
                    + " another container");
        }
        for (Method method : methods) {
            int modifiers = method.getModifiers();
            if (Modifier.isFinal(modifiers) || Modifier.isStatic(modifiers) || !Modifier.isPublic(modifiers)) {
                throw new JadeException(method + " must be public, not static and not final for "
                        + implementation.getName() + " to be placed in another container");
            }
        }
    }

    /** The stub class, in a class loader of its own that sees the implementation's classes. */
    private static Class<?> compile(StubSource source) {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        if (javac == null) {
            throw new JadeException("no Java compiler in this runtime: placing agents needs a JDK, not a JRE");
        }
        DiagnosticCollector<JavaFileObject> problems = new DiagnosticCollector<>();
        Output output = new Output(javac.getStandardFileManager(problems, null, null));
        List<String> options = List.of("-classpath", classPath(source), "-proc:none", "-nowarn", "--release", "17");
        JavaFileObject unit = new InMemory(source.className(), JavaFileObject.Kind.SOURCE, source.text());
        if (!javac.getTask(null, output, problems, options, null, List.of(unit)).call()) {
            throw new JadeException("cannot compile the stub " + source.className() + ":\n"
                    + problems.getDiagnostics().stream().map(Object::toString).collect(Collectors.joining("\n")));
        }
        byte[] bytes = output.classes.get(source.className()).bytes.toByteArray();
        return new StubLoader(source.implementation().getClassLoader()).define(source.className(), bytes);
    }

    /** Where the classes the stub names were loaded from, then this JVM's class path. */
    private static String classPath(StubSource source) {
        Set<Class<?>> named = new LinkedHashSet<>(List.of(BodyStub.class, AgentImplementation.class));
        for (Class<?> type = source.implementation(); type != null; type = type.getSuperclass()) {
            named.add(type);
        }
        for (Method method : source.methods()) {
            named.add(method.getReturnType());
            named.addAll(List.of(method.getParameterTypes()));
        }
        Set<String> entries = new LinkedHashSet<>();
        for (Class<?> type : named) {
            while (type.isArray()) {
                type = type.getComponentType();
            }
            CodeSource origin = type.getProtectionDomain().getCodeSource();
            if (origin != null && origin.getLocation() != null) {
                try {
                    entries.add(new File(origin.getLocation().toURI()).getPath());
                } catch (URISyntaxException | IllegalArgumentException notAFile) {
                    // Loaded from elsewhere than a folder or a jar: this JVM's class path may still have it.
                }
            }
        }
        entries.add(System.getProperty("java.class.path"));
        return String.join(File.pathSeparator, entries);
    }

    /** A compilation unit or a class file, in memory. */
    private static final class InMemory extends SimpleJavaFileObject {
        private final String text;
        private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();

        InMemory(String className, Kind kind, String text) {
            super(URI.create("memory:///" + className.replace('.', '/') + kind.extension), kind);
            this.text = text;
        }

        @Override
        public CharSequence getCharContent(boolean ignoreEncodingErrors) {
            return text;
        }

        @Override
        public OutputStream openOutputStream() {
            return bytes;
        }
    }

    /** Keeps the class files javac writes. */
    private static final class Output extends ForwardingJavaFileManager<JavaFileManager> {
        private final Map<String, InMemory> classes = new HashMap<>();

        Output(JavaFileManager standard) {
            super(standard);
        }

        @Override
        public JavaFileObject getJavaFileForOutput(Location location, String className, JavaFileObject.Kind kind,
                FileObject sibling) {
            InMemory file = new InMemory(className, kind, "");
            classes.put(className, file);
            return file;
        }
    }

    /** Defines one stub class; sees the implementation's classes and this module's {@link BodyStub}. */
    private static final class StubLoader extends ClassLoader {
        StubLoader(ClassLoader parent) {
            super(parent);
        }

        @Override
        protected Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
            if (name.equals(BodyStub.class.getName())) {
                return BodyStub.class;
            }
            return super.loadClass(name, resolve);
        }

        Class<?> define(String name, byte[] bytes) {
            return defineClass(name, bytes, 0, bytes.length);
        }
    }
}
