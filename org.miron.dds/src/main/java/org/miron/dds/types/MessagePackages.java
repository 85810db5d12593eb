package org.miron.dds.types;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import java.util.function.Predicate;
import java.util.stream.Stream;
import javax.xml.parsers.DocumentBuilderFactory;

/**
 * Loads message packages laid out as ROS 2 packages: {@code msg/*.msg} and {@code msg/*.idl} under
 * a folder whose {@code package.xml} names the package (else the folder's name does). A package
 * that redefines a type the bridge ships wins, with a warning. No ROS 2 installation is needed and
 * nothing is generated: the definitions are read at start-up.
 */
public final class MessagePackages {
    private MessagePackages() {
    }

    /**
     * The registry of the packages' types.
     *
     * @param shipped  whether a pkg/Name is a type the bridge ships (for the warning)
     * @param warnings receives {@code FILE:1:1: warning [dds-types]: ...} lines
     */
    public static TypeRegistry load(List<Path> folders, Predicate<String> shipped, Consumer<String> warnings)
            throws DefinitionException, IOException {
        Map<String, MsgType> types = new LinkedHashMap<>();
        for (Path folder : folders) {
            String pkg = packageName(folder);
            Path msg = folder.resolve("msg");
            if (!Files.isDirectory(msg)) {
                throw new DefinitionException(folder.toString(), 1, 1, "no msg/ folder in the message package " + pkg);
            }
            List<Path> files;
            try (Stream<Path> s = Files.list(msg)) {
                files = s.filter(p -> p.toString().endsWith(".msg") || p.toString().endsWith(".idl")).sorted().toList();
            }
            for (Path file : files) {
                String text = Files.readString(file, StandardCharsets.UTF_8);
                String fileName = file.getFileName().toString();
                String base = fileName.substring(0, fileName.lastIndexOf('.'));
                List<MsgType> defined = new ArrayList<>();
                if (fileName.endsWith(".msg")) {
                    if (!base.matches("[A-Z][A-Za-z0-9]*")) {
                        throw new DefinitionException(file.toString(), 1, 1, "a message file is named in CamelCase (Name.msg), not " + fileName);
                    }
                    defined.add(MsgParser.parse(file.toString(), pkg, base, text));
                } else {
                    if (Files.exists(msg.resolve(base + ".msg"))) {
                        continue; // rosidl's .idl generated from the .msg beside it: the same type
                    }
                    for (MsgType t : IdlParser.parse(file.toString(), text)) {
                        if (!t.pkg().equals(pkg)) {
                            throw new DefinitionException(file.toString(), 1, 1, "defines " + t.fullName() + " in the package " + pkg
                                    + " (module " + t.pkg() + " should be " + pkg + ")");
                        }
                        defined.add(t);
                    }
                }
                for (MsgType t : defined) {
                    MsgType before = types.put(t.fullName(), t);
                    if (before != null) {
                        throw new DefinitionException(file.toString(), 1, 1, t.fullName() + " is defined twice (also in " + before.file() + ")");
                    }
                    if (shipped.test(t.fullName()) || TypeRegistry.SHIPPED.contains(t.fullName())) {
                        warnings.accept(file + ":1:1: warning [dds-types]: " + t.fullName()
                                + " redefines a type the bridge ships; this definition is used");
                    }
                }
            }
        }
        return new TypeRegistry(types);
    }

    /** package.xml's {@code <name>}, else the folder's name. */
    static String packageName(Path folder) throws DefinitionException {
        Path xml = folder.resolve("package.xml");
        String name = folder.toAbsolutePath().normalize().getFileName().toString();
        if (Files.isRegularFile(xml)) {
            try {
                DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
                f.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
                org.w3c.dom.NodeList n = f.newDocumentBuilder().parse(xml.toFile()).getDocumentElement().getElementsByTagName("name");
                if (n.getLength() > 0) {
                    name = n.item(0).getTextContent().trim();
                }
            } catch (Exception e) { // a parser's many checked exceptions: all mean the file is not usable XML
                throw new DefinitionException(xml.toString(), 1, 1, "cannot read package.xml: " + e.getMessage());
            }
        }
        if (!name.matches("[a-z][a-z0-9_]*")) {
            throw new DefinitionException(Files.isRegularFile(xml) ? xml.toString() : folder.toString(), 1, 1,
                    "a ROS 2 package name is lower case letters, digits and underscores, not " + name);
        }
        return name;
    }
}
