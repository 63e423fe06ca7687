package masl.jade;

import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import masl.runtime.AgentImplementation;

/**
 * Makes stubs: instances of a subclass of an agent's implementation class whose primitives, instead
 * of running, hand their name's index and arguments to a {@link BodyStub}. The runtime and the
 * generated program call a stub exactly as the implementation ({@code self.logln(…)}, or inside
 * {@code ctx.invoke(…)}), so a program cannot tell where its agent's body is.
 *
 * <p>The subclass is written as a class file here (straight-line code, version 52: no stack map
 * frames needed), because the JDK offers no public way to subclass a class at run time and the
 * project takes no bytecode library for one class. Each overriding method is:
 * <pre>{@code
 * public R m(A0 a0, A1 a1) { return (R) stub.call(i, new Object[] {box(a0), box(a1)}); }  // unboxed if R is primitive
 * }</pre>
 * The implementation class and its primitives' methods must be public and not final, with a public
 * no-argument constructor.
 */
final class StubClasses {

    private static final String STUB = BodyStub.class.getName().replace('.', '/');
    private static final String STUB_DESCRIPTOR = "L" + STUB + ";";

    private StubClasses() {
    }

    /**
     * A stub of {@code implementation} forwarding {@code methods} (by their index in the list) to
     * {@code stub}. Methods of the class that are not in the list run as the class has them.
     *
     * @throws JadeException if the class or one of the methods cannot be overridden
     */
    static AgentImplementation instantiate(Class<? extends AgentImplementation> implementation, List<Method> methods,
            BodyStub stub) {
        check(implementation, methods);
        String name = "masl/jade/stub/" + implementation.getSimpleName() + "$Stub";
        byte[] bytes = new ClassWriter(name, implementation, methods).write();
        try {
            Class<?> stubClass = new StubLoader(implementation.getClassLoader()).define(name.replace('/', '.'), bytes);
            return (AgentImplementation) stubClass.getConstructor(BodyStub.class).newInstance(stub);
        } catch (ReflectiveOperationException | LinkageError e) {
            throw new JadeException("cannot make a stub of " + implementation.getName() + ": " + e, e);
        }
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

    /** The class file of one stub class. */
    private static final class ClassWriter {
        private static final int MAX_STACK = 8;

        private final String name;
        private final String superName;
        private final List<Method> methods;
        private final ByteArrayOutputStream constantBytes = new ByteArrayOutputStream();
        private final DataOutputStream constants = new DataOutputStream(constantBytes);
        private final Map<String, Integer> constantIndex = new HashMap<>();
        private int constantCount = 1;

        ClassWriter(String name, Class<?> superclass, List<Method> methods) {
            this.name = name;
            this.superName = superclass.getName().replace('.', '/');
            this.methods = methods;
        }

        byte[] write() {
            try {
                ByteArrayOutputStream body = new ByteArrayOutputStream();
                DataOutputStream out = new DataOutputStream(body);
                out.writeShort(0x1031); // public final super synthetic
                out.writeShort(classRef(name));
                out.writeShort(classRef(superName));
                out.writeShort(0); // interfaces
                out.writeShort(1); // fields: private final BodyStub stub
                out.writeShort(0x0012);
                out.writeShort(utf8("stub"));
                out.writeShort(utf8(STUB_DESCRIPTOR));
                out.writeShort(0);
                out.writeShort(1 + methods.size());
                writeConstructor(out);
                for (int i = 0; i < methods.size(); i++) {
                    writeForwarder(out, i, methods.get(i));
                }
                out.writeShort(0); // class attributes
                ByteArrayOutputStream file = new ByteArrayOutputStream();
                DataOutputStream header = new DataOutputStream(file);
                header.writeInt(0xCAFEBABE);
                header.writeShort(0);
                header.writeShort(52);
                header.writeShort(constantCount);
                constantBytes.writeTo(file);
                body.writeTo(file);
                return file.toByteArray();
            } catch (IOException impossible) {
                throw new UncheckedIOException(impossible);
            }
        }

        /** {@code public Stub(BodyStub stub) { super(); this.stub = stub; }} */
        private void writeConstructor(DataOutputStream out) throws IOException {
            ByteArrayOutputStream code = new ByteArrayOutputStream();
            DataOutputStream c = new DataOutputStream(code);
            c.writeByte(0x2a); // aload_0
            c.writeByte(0xb7); // invokespecial
            c.writeShort(methodRef(superName, "<init>", "()V", false));
            c.writeByte(0x2a); // aload_0
            c.writeByte(0x2b); // aload_1
            c.writeByte(0xb5); // putfield
            c.writeShort(fieldRef(name, "stub", STUB_DESCRIPTOR));
            c.writeByte(0xb1); // return
            writeMethod(out, "<init>", "(" + STUB_DESCRIPTOR + ")V", 2, 2, code.toByteArray());
        }

        private void writeForwarder(DataOutputStream out, int index, Method method) throws IOException {
            ByteArrayOutputStream code = new ByteArrayOutputStream();
            DataOutputStream c = new DataOutputStream(code);
            c.writeByte(0x2a); // aload_0
            c.writeByte(0xb4); // getfield
            c.writeShort(fieldRef(name, "stub", STUB_DESCRIPTOR));
            pushInt(c, index);
            Class<?>[] parameters = method.getParameterTypes();
            pushInt(c, parameters.length);
            c.writeByte(0xbd); // anewarray
            c.writeShort(classRef("java/lang/Object"));
            int slot = 1;
            for (int i = 0; i < parameters.length; i++) {
                c.writeByte(0x59); // dup
                pushInt(c, i);
                slot += load(c, parameters[i], slot);
                c.writeByte(0x53); // aastore
            }
            c.writeByte(0xb9); // invokeinterface
            c.writeShort(methodRef(STUB, "call", "(I[Ljava/lang/Object;)Ljava/lang/Object;", true));
            c.writeByte(3);
            c.writeByte(0);
            returnResult(c, method.getReturnType());
            writeMethod(out, method.getName(), descriptor(method), MAX_STACK, slot, code.toByteArray());
        }

        private void writeMethod(DataOutputStream out, String methodName, String descriptor, int maxStack,
                int maxLocals, byte[] code) throws IOException {
            out.writeShort(0x0001); // public
            out.writeShort(utf8(methodName));
            out.writeShort(utf8(descriptor));
            out.writeShort(1);
            out.writeShort(utf8("Code"));
            out.writeInt(12 + code.length);
            out.writeShort(maxStack);
            out.writeShort(maxLocals);
            out.writeInt(code.length);
            out.write(code);
            out.writeShort(0); // exception table
            out.writeShort(0); // attributes
        }

        /** Loads parameter {@code type} from {@code slot}, boxed; returns the slots it takes. */
        private int load(DataOutputStream c, Class<?> type, int slot) throws IOException {
            int opcode = type == long.class ? 0x16 : type == float.class ? 0x17 : type == double.class ? 0x18
                    : type.isPrimitive() ? 0x15 : 0x19; // lload fload dload iload aload
            c.writeByte(opcode);
            c.writeByte(slot);
            if (type.isPrimitive()) {
                String box = box(type);
                c.writeByte(0xb8); // invokestatic
                c.writeShort(methodRef(box, "valueOf", "(" + descriptor(type) + ")L" + box + ";", false));
            }
            return type == long.class || type == double.class ? 2 : 1;
        }

        private void returnResult(DataOutputStream c, Class<?> type) throws IOException {
            if (type == void.class) {
                c.writeByte(0x57); // pop
                c.writeByte(0xb1); // return
            } else if (!type.isPrimitive()) {
                c.writeByte(0xc0); // checkcast
                c.writeShort(classRef(type.isArray() ? descriptor(type) : type.getName().replace('.', '/')));
                c.writeByte(0xb0); // areturn
            } else {
                String box = box(type);
                c.writeByte(0xc0);
                c.writeShort(classRef(box));
                c.writeByte(0xb6); // invokevirtual
                c.writeShort(methodRef(box, type.getName() + "Value", "()" + descriptor(type), false));
                c.writeByte(type == long.class ? 0xad : type == float.class ? 0xae : type == double.class ? 0xaf
                        : 0xac); // lreturn freturn dreturn ireturn
            }
        }

        private void pushInt(DataOutputStream c, int value) throws IOException {
            if (value <= 5) {
                c.writeByte(0x03 + value); // iconst_<n>
            } else if (value <= Byte.MAX_VALUE) {
                c.writeByte(0x10); // bipush
                c.writeByte(value);
            } else {
                c.writeByte(0x11); // sipush
                c.writeShort(value);
            }
        }

        private static String box(Class<?> primitive) {
            Class<?> boxed = java.lang.invoke.MethodType.methodType(primitive).wrap().returnType();
            return boxed.getName().replace('.', '/');
        }

        private static String descriptor(Method method) {
            StringBuilder descriptor = new StringBuilder("(");
            for (Class<?> parameter : method.getParameterTypes()) {
                descriptor.append(descriptor(parameter));
            }
            return descriptor.append(')').append(descriptor(method.getReturnType())).toString();
        }

        private static String descriptor(Class<?> type) {
            return java.lang.invoke.MethodType.methodType(type).toMethodDescriptorString().substring(2);
        }

        private int utf8(String text) throws IOException {
            return constant("U" + text, () -> {
                constants.writeByte(1);
                constants.writeUTF(text);
            });
        }

        private int classRef(String internalName) throws IOException {
            int nameIndex = utf8(internalName);
            return constant("C" + internalName, () -> {
                constants.writeByte(7);
                constants.writeShort(nameIndex);
            });
        }

        private int nameAndType(String memberName, String descriptor) throws IOException {
            int nameIndex = utf8(memberName);
            int typeIndex = utf8(descriptor);
            return constant("N" + memberName + " " + descriptor, () -> {
                constants.writeByte(12);
                constants.writeShort(nameIndex);
                constants.writeShort(typeIndex);
            });
        }

        private int fieldRef(String owner, String fieldName, String descriptor) throws IOException {
            int ownerIndex = classRef(owner);
            int nat = nameAndType(fieldName, descriptor);
            return constant("F" + owner + "." + fieldName, () -> {
                constants.writeByte(9);
                constants.writeShort(ownerIndex);
                constants.writeShort(nat);
            });
        }

        private int methodRef(String owner, String methodName, String descriptor, boolean ofInterface)
                throws IOException {
            int ownerIndex = classRef(owner);
            int nat = nameAndType(methodName, descriptor);
            return constant("M" + owner + "." + methodName + descriptor, () -> {
                constants.writeByte(ofInterface ? 11 : 10);
                constants.writeShort(ownerIndex);
                constants.writeShort(nat);
            });
        }

        private interface ConstantWriter {
            void write() throws IOException;
        }

        private int constant(String key, ConstantWriter writer) throws IOException {
            Integer known = constantIndex.get(key);
            if (known != null) {
                return known;
            }
            writer.write();
            int index = constantCount++;
            constantIndex.put(key, index);
            return index;
        }
    }
}
