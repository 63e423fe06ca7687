package masl.runtime.descriptor;

import java.io.UncheckedIOException;
import java.net.URI;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Supplier;

/**
 * Loads agent type descriptors, validates them (agent-types.md, "Rules the loader enforces") and
 * resolves their supertypes, along an {@link AgentPath}. Implementation classes are loaded through
 * {@link AgentPath#classLoader} with the path's resource loader as parent.
 *
 * <p>Every type that names no {@code super_full_class_name} extends the <em>root type</em> unless it is
 * a root itself: a descriptor named {@link #ROOT_FILE} or declaring the root class ({@link #ROOT_TYPE},
 * {@code masl.agents.Default}). The root type is the {@code Default.xml} found first from the subtype:
 * in its folder, then along the agent path, then among the shipped descriptors; so a user's own
 * {@code Default.xml}, whatever class it names, is the root of the types next to it (components.md,
 * "Agent path"). Only when no {@code Default.xml} is found is the root class looked up by name like any
 * supertype. A loader built with a null root type has no implicit supertype.
 *
 * <p>A supertype is found by class name, first match wins (a candidate's {@code full_class_name}
 * must match): in the subtype's folder as {@code SimpleName.xml} or {@code package/path/SimpleName.xml},
 * then as any {@code .xml} file there; then under those two names on the agent path and among the
 * classpath resources; then as any {@code .xml} file in the path's folders (recursively) and jars.
 * {@link #loadByClassName} searches the same way without a subtype's folder.
 *
 * <p>Loaded types are cached by location and by class name (the first type loaded for a class name
 * is the one {@link #loadByClassName} returns). Thread-safe: loading is serialised.
 *
 * <p>Every loading method throws the unchecked {@link DescriptorException}, listing all the problems
 * of the descriptor (and of a faulty supertype's descriptor after them).
 */
public final class DescriptorLoader {

    /** The implementation class of the type every other type extends. */
    public static final String ROOT_TYPE = "masl.agents.Default";

    /** The file name of a root type's descriptor. */
    public static final String ROOT_FILE = "Default.xml";

    /** Resources of no class loader: for searching one folder alone. */
    private static final ClassLoader EMPTY_RESOURCES = new ClassLoader(null) {
    };

    /** Whether this thread is inside {@link #readingValidated}. */
    private static final ThreadLocal<Boolean> VALIDATED_BEFORE = ThreadLocal.withInitial(() -> false);

    private final AgentPath agentPath;
    private final String rootType;
    private final ClassLoader implementationClasses;
    private final Map<URI, AgentType> byLocation = new HashMap<>();
    private final Map<String, AgentType> byClassName = new HashMap<>();
    /** Class names of the descriptors being loaded, outermost first: a supertype among them is a cycle. */
    private final List<String> loading = new ArrayList<>();

    /** A loader whose types implicitly extend {@code masl.agents.Default}. */
    public DescriptorLoader(AgentPath agentPath) {
        this(agentPath, ROOT_TYPE);
    }

    /**
     * @param rootType the implementation class of the implicit supertype, or null for none
     */
    public DescriptorLoader(AgentPath agentPath, String rootType) {
        this.agentPath = agentPath;
        this.rootType = rootType;
        this.implementationClasses = agentPath.classLoader(agentPath.resources());
    }

    public AgentPath agentPath() {
        return agentPath;
    }

    /** The class loader the implementation classes were checked with; use it to instantiate them. */
    public ClassLoader implementationClasses() {
        return implementationClasses;
    }

    /**
     * Runs {@code action} with the descriptors this thread loads meanwhile read without checking them
     * against the schema (compiling the schema is most of a cold load), nor their Java classes against
     * them (reflection on each class, 15 ms of a 0.25 s run from the cache). Only for descriptors and
     * classes validated already: a program the cache of compiled missions holds was translated against
     * exactly these descriptor bytes and these agent path and class path files, or it would have
     * another key. Every other rule is still enforced.
     */
    public static <T> T readingValidated(Supplier<T> action) {
        boolean outer = VALIDATED_BEFORE.get();
        VALIDATED_BEFORE.set(true);
        try {
            return action.get();
        } finally {
            VALIDATED_BEFORE.set(outer);
        }
    }

    /**
     * Loads the descriptor in {@code file}, and its supertypes.
     *
     * @throws DescriptorException when it or a supertype has problems
     */
    public AgentType load(Path file) {
        return load(DescriptorSource.ofFile(file));
    }

    /**
     * Loads a descriptor found by {@link AgentPath#find}, and its supertypes.
     *
     * @throws DescriptorException when it or a supertype has problems
     */
    public synchronized AgentType load(DescriptorSource source) {
        AgentType cached = byLocation.get(source.uri());
        if (cached != null) {
            return cached;
        }
        Problems problems = new Problems(source.displayName());
        boolean validatedBefore = VALIDATED_BEFORE.get();
        DescriptorReader.Result read = DescriptorReader.read(source, !validatedBefore && !ShippedDescriptors.contains(source));
        problems.addAll(read.problems());
        Declaration declaration = read.root() == null ? null : DeclarationReader.read(read.root(), problems);
        if (declaration == null) {
            if (problems.isEmpty()) {
                problems.at(0, 0, "no <Agent> element");
            }
            problems.throwIfAny();
        }
        loading.add(declaration.fullClassName());
        try {
            boolean root = declaration.superFullClassName() == null && isRoot(declaration, source);
            AgentType supertype = root ? null
                    : declaration.superFullClassName() != null
                            ? resolveSupertype(declaration.superFullClassName(), declaration, source, problems)
                            : resolveRoot(declaration, source, problems);
            if (!root && supertype == null) {
                problems.throwIfAny();
            }
            AgentType type = TypeAssembler.assemble(declaration, supertype, source, problems);
            if (!validatedBefore) {
                ImplementationChecker.check(declaration, supertype, implementationClasses, problems);
            }
            problems.throwIfAny();
            byLocation.put(source.uri(), type);
            byClassName.putIfAbsent(type.fullClassName(), type);
            return type;
        } finally {
            loading.remove(loading.size() - 1);
        }
    }

    /**
     * Loads the type whose descriptor's {@code full_class_name} is {@code fullClassName}, looked up on the
     * agent path and among the classpath resources (see the class comment).
     *
     * @throws DescriptorException when no descriptor declares that class, or it has problems
     */
    public synchronized AgentType loadByClassName(String fullClassName) {
        AgentType cached = byClassName.get(fullClassName);
        if (cached != null) {
            return cached;
        }
        Problems problems = new Problems("agent path " + agentPath);
        Optional<DescriptorSource> found = locate(fullClassName, null, problems);
        if (found.isEmpty()) {
            problems.at(0, 0, "no descriptor with full_class_name=\"" + fullClassName + "\" on the agent path"
                    + " or among the shipped descriptors");
            problems.throwIfAny();
        }
        return load(found.get());
    }

    /** A descriptor naming no supertype is a root when there is no implicit root, or it is named or declares one. */
    private boolean isRoot(Declaration declaration, DescriptorSource source) {
        return rootType == null || rootType.equals(declaration.fullClassName()) || source.fileName().equals(ROOT_FILE);
    }

    /** The implicit supertype: the {@code Default.xml} found first from {@code source}, else the root class. */
    private AgentType resolveRoot(Declaration declaration, DescriptorSource source, Problems problems) {
        Optional<DescriptorSource> named;
        try {
            named = agentPath.find(ROOT_FILE, folderOf(source));
        } catch (UncheckedIOException e) {
            problems.at(0, 0, "cannot search for " + ROOT_FILE + ": " + e.getMessage());
            return null;
        }
        if (named.isEmpty()) {
            return resolveSupertype(rootType, declaration, source, problems);
        }
        Optional<String> rootClass = DescriptorReader.peekFullClassName(named.get());
        if (rootClass.isPresent() && isCycle(rootClass.get(), declaration, problems)) {
            return null;
        }
        return loadSupertype(named.get(), declaration, problems);
    }

    /** The loaded supertype, or null after adding to {@code problems} why there is none. */
    private AgentType resolveSupertype(String name, Declaration declaration, DescriptorSource source,
            Problems problems) {
        if (isCycle(name, declaration, problems)) {
            return null;
        }
        AgentType cached = byClassName.get(name);
        if (cached != null) {
            return cached;
        }
        Optional<DescriptorSource> found = locate(name, folderOf(source), problems);
        if (found.isEmpty()) {
            problems.at(declaration.agent(), role(declaration) + " '" + name + "' not found: no descriptor with "
                    + "full_class_name=\"" + name + "\" next to this file, on the agent path or among the shipped "
                    + "descriptors");
            return null;
        }
        return loadSupertype(found.get(), declaration, problems);
    }

    private boolean isCycle(String supertypeName, Declaration declaration, Problems problems) {
        int cycleStart = loading.indexOf(supertypeName);
        if (cycleStart < 0) {
            return false;
        }
        List<String> cycle = new ArrayList<>(loading.subList(cycleStart, loading.size()));
        cycle.add(supertypeName);
        problems.at(declaration.agent(), "cycle in supertypes: " + String.join(" -> ", cycle));
        return true;
    }

    private AgentType loadSupertype(DescriptorSource found, Declaration declaration, Problems problems) {
        try {
            return load(found);
        } catch (DescriptorException e) {
            String name = DescriptorReader.peekFullClassName(found).orElse(found.fileName());
            problems.at(declaration.agent(), role(declaration) + " '" + name + "' (" + found.displayName()
                    + ") has errors");
            problems.addAll(e.problems());
            return null;
        }
    }

    private static String role(Declaration declaration) {
        return declaration.superFullClassName() != null ? "supertype" : "implicit supertype";
    }

    private static Path folderOf(DescriptorSource source) {
        return source.file().map(Path::getParent).orElse(null);
    }

    private Optional<DescriptorSource> locate(String className, Path nearFolder, Problems problems) {
        String simpleName = className.substring(className.lastIndexOf('.') + 1);
        List<String> conventionalNames = List.of(simpleName + ".xml", className.replace('.', '/') + ".xml");
        // In search order; each is only listed when the ones before hold no descriptor of the class.
        List<Supplier<List<DescriptorSource>>> searches = new ArrayList<>();
        if (nearFolder != null) {
            AgentPath nextToSubtype = AgentPath.of(List.of(nearFolder), EMPTY_RESOURCES);
            conventionalNames.forEach(name -> searches.add(() -> nextToSubtype.findAll(name, null)));
            searches.add(() -> AgentPath.xmlFilesIn(nearFolder));
        }
        conventionalNames.forEach(name -> searches.add(() -> agentPath.findAll(name, null)));
        searches.add(agentPath::allDescriptorsInEntries);
        try {
            return searches.stream().flatMap(search -> search.get().stream())
                    .filter(source -> declares(source, className)).findFirst();
        } catch (UncheckedIOException e) {
            problems.at(0, 0, "cannot search for the descriptor of '" + className + "': " + e.getMessage());
            return Optional.empty();
        }
    }

    private static boolean declares(DescriptorSource source, String className) {
        return DescriptorReader.peekFullClassName(source).filter(className::equals).isPresent();
    }
}
