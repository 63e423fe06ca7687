package masl.jade.trust;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jade.lang.acl.ACLMessage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import masl.jade.acl.Conversations;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A control message obeyed only with the signature of the mission's secret, for its receiver, of what it says. */
class MissionSecretTest {

    private final MissionSecret secret = MissionSecret.generate();

    @Test
    void aSignatureHoldsForItsSenderReceiverAndContentOnly() {
        ACLMessage end = end("{}");
        secret.sign(end, "masl-coordinator", "masl-container-c2", 1);
        assertTrue(secret.signed(end, "masl-coordinator", "masl-container-c2"));
        assertFalse(secret.signed(end, "masl-coordinator", "masl-container-c3"), "replayed to another container");
        assertFalse(secret.signed(end, "b", "masl-container-c2"), "claimed by another sender");
        assertFalse(MissionSecret.generate().signed(end, "masl-coordinator", "masl-container-c2"),
                "another mission's secret");
        end.setContent("{\"agents\":[]}");
        assertFalse(secret.signed(end, "masl-coordinator", "masl-container-c2"), "content changed");
        ACLMessage unsigned = end("{}");
        assertFalse(secret.signed(unsigned, "masl-coordinator", "masl-container-c2"));
        ACLMessage place = end("{}");
        place.setConversationId(Conversations.PLACE);
        place.addUserDefinedParameter(MissionSecret.PARAMETER, end.getUserDefinedParameter(MissionSecret.PARAMETER));
        assertFalse(secret.signed(place, "masl-coordinator", "masl-container-c2"),
                "another conversation with the same signature");
        ACLMessage renumbered = end("{}");
        secret.sign(renumbered, "masl-coordinator", "masl-container-c2", 1);
        renumbered.addUserDefinedParameter(MissionSecret.SEQUENCE, "2");
        assertFalse(secret.signed(renumbered, "masl-coordinator", "masl-container-c2"), "a copy given another number");
        ACLMessage answer = end("{\"result\":5}");
        answer.setInReplyTo("masl-coordinator-1");
        secret.sign(answer, "b", "masl-coordinator", 1);
        answer.setInReplyTo("masl-coordinator-2");
        assertFalse(secret.signed(answer, "b", "masl-coordinator"), "an answer moved to another request");
    }

    @Test
    void theFileOnlyItsOwnerCanRead(@TempDir Path folder) throws IOException {
        Path file = folder.resolve("mission.secret");
        try (SecretFile shared = secret.writeTo(file)) {
            assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(file)));
            assertEquals(1, Files.list(folder).count(), "no file left beside it");
            ACLMessage end = end("{}");
            secret.sign(end, "masl-coordinator", "b", 7);
            assertTrue(MissionSecret.readFrom(file).signed(end, "masl-coordinator", "b"));
        }
        assertFalse(Files.exists(file), "the secret outlived its mission");
        Files.writeString(file, "not a secret\n");
        IOException unreadable = assertThrows(IOException.class, () -> MissionSecret.readFrom(file));
        assertEquals(file + " holds no mission secret (64 hexadecimal digits)", unreadable.getMessage());
    }

    @Test
    void aFileThatExistsIsNeitherOverwrittenNorDeleted(@TempDir Path folder) throws IOException {
        Path notes = Files.writeString(folder.resolve("notes.txt"), "my notes\n");
        IOException refused = assertThrows(IOException.class, () -> secret.writeTo(notes));
        assertTrue(refused.getMessage().startsWith("it exists, and the mission's secret is written only to a file"
                + " the mission creates"), refused.getMessage());
        assertEquals("my notes\n", Files.readString(notes));
        Path link = Files.createSymbolicLink(folder.resolve("link"), folder.resolve("nowhere"));
        assertThrows(IOException.class, () -> secret.writeTo(link));
        assertFalse(Files.exists(folder.resolve("nowhere")), "a secret written through a symbolic link");
    }

    @Test
    void aFilePutInPlaceOfTheSecretIsNotDeleted(@TempDir Path folder) throws IOException {
        Path file = folder.resolve("mission.secret");
        try (SecretFile shared = secret.writeTo(file)) {
            Files.delete(file);
            Files.writeString(file, "another mission's\n");
        }
        assertEquals("another mission's\n", Files.readString(file));
    }

    @Test
    void eachPlatformHasItsOwnDefaultFile(@TempDir Path folder) {
        assertNotEquals(SecretFile.defaultFor(folder, 1099), SecretFile.defaultFor(folder, 1100));
        assertEquals(folder, SecretFile.defaultFor(folder, 1099).getParent());
    }

    private static ACLMessage end(String content) {
        ACLMessage message = new ACLMessage(ACLMessage.REQUEST);
        message.setConversationId(Conversations.END);
        message.setReplyWith("masl-coordinator-x");
        message.setContent(content);
        return message;
    }
}
