#!/usr/bin/env python3
# generate_zip.py - makes the zip reader's seed corpus (fuzz/corpus/zip/):
# good zips (deflated, stored, with macOS's __MACOSX/ files) and one of
# each kind the reader refuses (a path that climbs out, an absolute path,
# a link, two sources of one name, a bomb, a bomb whose headers lie, a
# wrong CRC, encryption, a cut end, nothing).  Run from the repository
# root:  python3 fuzz/corpus/generate_zip.py
import struct
import zipfile

D = 'fuzz/corpus/zip/'
SRC = b'#include <stdio.h>\nint main(void) { puts("P1\\n1 1\\n1"); return 0; }\n'


def make(name, entries, method=zipfile.ZIP_DEFLATED):
    with zipfile.ZipFile(D + name, 'w', method) as z:
        for n, data, mode in entries:
            info = zipfile.ZipInfo(n)
            info.compress_type = method
            if mode is not None:
                info.create_system = 3
                info.external_attr = mode << 16
            z.writestr(info, data)


def patch(name, local_offset, central_offset, fmt, value):
    """Sets a field of the first entry's local and central headers."""
    b = bytearray(open(D + name, 'rb').read())
    struct.pack_into(fmt, b, local_offset, value)
    struct.pack_into(fmt, b, b.find(b'PK\x01\x02') + central_offset, value)
    open(D + name, 'wb').write(b)


make('ok-deflated.zip', [('ana/main.c', SRC, None), ('ana/vector.h', b'/* h */\n', None),
                         ('ana/notes.txt', b'x', None), ('ana/', b'', 0o040755)])
make('ok-stored.zip', [('main.c', SRC, None)], zipfile.ZIP_STORED)
make('ok-macosx.zip', [('main.c', SRC, None), ('__MACOSX/._main.c', b'junk', None)])
make('bad-climb.zip', [('../x.c', b'int x;\n', None)])
make('bad-absolute.zip', [('/tmp/x.c', b'int x;\n', None)])
make('bad-link.zip', [('x.h', b'/etc/passwd', 0o120777)])
make('bad-duplicate.zip', [('a/main.c', SRC, None), ('b/main.c', SRC, None)])
make('bad-bomb.zip', [('main.c', b'\0' * (2 << 20), None)])
make('bad-liar.zip', [('main.c', b'/' * (2 << 20), None)])
patch('bad-liar.zip', 22, 24, '<I', 100)          # uncompressed size
make('bad-crc.zip', [('main.c', SRC, None)], zipfile.ZIP_STORED)
patch('bad-crc.zip', 14, 16, '<I', 0x12345678)    # CRC-32
make('bad-encrypted.zip', [('e.c', b'int x;\n', None)], zipfile.ZIP_STORED)
patch('bad-encrypted.zip', 6, 8, '<H', 1)         # flags: encrypted
open(D + 'bad-truncated.zip', 'wb').write(open(D + 'ok-deflated.zip', 'rb').read()[:-30])
open(D + 'bad-empty.zip', 'wb').write(b'')
