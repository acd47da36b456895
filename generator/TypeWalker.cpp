//===- TypeWalker.cpp - Types reachable from roots, into the model
//----------===//
//
// See TypeWalker.h.
//
//===----------------------------------------------------------------------===//
#include "TypeWalker.h"
#include "Annotations.h"
#include "NameIndex.h"

#include "clang/AST/ASTContext.h"
#include "clang/AST/Attr.h"
#include "clang/AST/DeclCXX.h"
#include "clang/AST/DeclTemplate.h"
#include "clang/AST/Mangle.h"
#include "clang/AST/RecordLayout.h"
#include "clang/AST/RecursiveASTVisitor.h"
#include "clang/AST/VTableBuilder.h"
#include "clang/Basic/SourceManager.h"
#include "clang/Sema/Sema.h"
#include "llvm/ADT/StringExtras.h"
#include "llvm/Support/raw_ostream.h"

#include <algorithm>
#include <cstdlib>
#include <functional>

#include <algorithm>
#include <cstdlib>
#include <functional>

using namespace clang;

namespace symcr_gen {

std::uint32_t TypeWalker::fail(const WalkContext &C, const std::string &What,
                               const std::string &Why) {
  bool Grouped = !C.Group.empty() && C.Group.SkipHint != C.SkipHint;
  Sink->unrestorable(C.Where,
                     "'" + C.Path + "' reaches " + What + ", which cannot be " +
                         "checkpointed: " + Why,
                     C.SkipHint, Grouped ? &C.Group : nullptr);
  return symcr::kNoType;
}

/// The context for the object a pointer (raw or smart) at \p C points to. The
/// first such crossing marks the group: the member holding the pointer (or the
/// pointer itself at a root's top level), whose skip removes all beyond.
WalkContext intoPointee(const WalkContext &C, const std::string &PointerType) {
  WalkContext Target = C;
  Target.Path += "->";
  Target.Shallow = false;
  Target.AnonymousName.clear();
  if (Target.Group.empty())
    Target.Group = !C.Enclosing.empty()
                       ? C.Enclosing
                       : MemberRef{C.Path, C.SkipHint, PointerType, C.Where};
  return Target;
}

const RecordDecl *TypeWalker::completeDefinition(const RecordDecl *RD,
                                                 SourceLocation Where) {
  if (const RecordDecl *Definition = RD->getDefinition())
    return Definition;
  if (!S || RD->isDependentType() || !isa<ClassTemplateSpecializationDecl>(RD))
    return nullptr;
  QualType Type = Context.getRecordType(RD);
  if (S->isCompleteType(Where, Type))
    return RD->getDefinition();
  return nullptr;
}

bool TypeWalker::isSkippedType(const RecordDecl *RD, std::string &Why) {
  if (hasAnnotation(RD, "skip")) {
    Why = "SYMCR_SKIP on the type";
    return true;
  }
  for (const std::string &Key : recordKeys(RD)) {
    auto It = Select.SkippedTypes.find(Key);
    if (It != Select.SkippedTypes.end()) {
      Why = It->second;
      return true;
    }
  }
  return false;
}

/// Why a member of type \p Type is never restored and left to the new build, or
/// null. A const member is the new build's constant (writing it would be
/// undefined behaviour, and would undo a patch that changed it); a reference is
/// bound by the new build's constructor; a function or member pointer is code
/// of the old build (restoring one would be an arc-injection vector).
const char *TypeWalker::leftToNewBuild(QualType Type) const {
  QualType Canonical = Type.getCanonicalType();
  if (Canonical->isReferenceType())
    return "reference member: bound by the new build";
  QualType Element = Context.getBaseElementType(Canonical);
  if (Element.isConstQualified())
    return "const member: the new build's value is kept";
  if (Element->isMemberPointerType())
    return "member pointer: code of the old build";
  if (Element->isFunctionPointerType())
    return "function pointer: code of the old build";
  return nullptr;
}

std::uint32_t TypeWalker::reserve(const std::string &Key,
                                  const std::string &Name, bool &Fresh) {
  auto It = Program.TypeIndex.find(Key);
  if (It != Program.TypeIndex.end()) {
    Fresh = false;
    return It->second;
  }
  Fresh = true;
  std::uint32_t Index = static_cast<std::uint32_t>(Program.Types.size());
  Program.Types.emplace_back();
  Program.Types.back().Name = Name;
  Program.Types.back().HomeTU = TUIndex;
  Program.TypeIndex.emplace(Key, Index);
  return Index;
}

void TypeWalker::store(std::uint32_t Index, TypeModel Model,
                       const WalkContext &C) {
  TypeModel &Slot = Program.Types[Index];
  Model.Fingerprint = fingerprint(Model);
  if (!Slot.Fingerprint.empty()) {
    const bool SameUnit =
        Slot.FirstSeenIn == Program.TranslationUnits[TUIndex].Source;
    if (Slot.Fingerprint != Model.Fingerprint && SameUnit) {
      // Two types of one translation unit share a canonical name: no annotation
      // placement can fix that, only a name.
      Sink->error(C.Where,
                  "two different types are named '" + Model.Name +
                      "' (the second reached by '" + C.Path +
                      "'): give one of them a distinct name (a typedef or a "
                      "tag) to checkpoint both");
    } else if (Slot.Fingerprint != Model.Fingerprint &&
               Model.Name.find("(anonymous namespace)") != std::string::npos) {
      Sink->error(
          C.Where,
          "two different types are named '" + Model.Name + "' (reached by '" +
              C.Path + "' here and in '" + Slot.FirstSeenIn +
              "'): types with internal linkage in different translation "
              "units need distinct names to be checkpointed");
    } else if (Slot.Fingerprint != Model.Fingerprint) {
      Sink->error(
          C.Where,
          "type '" + Model.Name + "' (reached by '" + C.Path +
              "') is described differently in this translation unit "
              "than in '" +
              Slot.FirstSeenIn +
              "': annotations (pragmas) that select its members must be "
              "visible wherever the type is, e.g. in its header");
    }
    Slot.NeedsLifecycle |= Model.NeedsLifecycle;
    return;
  }
  Model.HomeTU = Slot.HomeTU;
  Model.NeedsLifecycle |= Slot.NeedsLifecycle;
  // Attached while the type was still being walked (a pointer inside it to
  // itself).
  Model.VtableSymbol = std::move(Slot.VtableSymbol);
  Model.VtableAddressPoint = Slot.VtableAddressPoint;
  Model.VtableKeyFunction = std::move(Slot.VtableKeyFunction);
  Model.DynamicTypes = std::move(Slot.DynamicTypes);
  Model.NotDynamicTypes = std::move(Slot.NotDynamicTypes);
  Model.DynamicTypesReachedBy = std::move(Slot.DynamicTypesReachedBy);
  Model.DynamicTypesReachedAt = std::move(Slot.DynamicTypesReachedAt);
  Model.DynamicTypesSkipHint = std::move(Slot.DynamicTypesSkipHint);
  Model.FirstSeenIn = Program.TranslationUnits[TUIndex].Source;
  Slot = std::move(Model);
}

std::uint32_t TypeWalker::walk(QualType Type, const WalkContext &C) {
  Type = Type.getCanonicalType();
  if (Type->isReferenceType())
    return fail(C, "a reference (" + Type.getAsString(*Policy) + ")",
                "a reference cannot be re-seated on restore");
  Type = Type.getUnqualifiedType();
  if (Type.isVolatileQualified())
    Type = Type.getUnqualifiedType();
  auto Key = std::make_pair(Type.getTypePtr(), C.Shallow);
  auto Done = Walked.find(Key);
  if (Done != Walked.end())
    return Done->second;
  std::uint32_t Result = symcr::kNoType;
  if (const auto *BT = dyn_cast<BuiltinType>(Type.getTypePtr()))
    Result = scalar(BT, C);
  else if (const auto *ET = Type->getAs<EnumType>())
    Result = enumeration(Type, ET->getDecl(), C);
  else if (const auto *AT = Context.getAsConstantArrayType(Type))
    Result = array(Type, AT, C);
  else if (Type->isArrayType())
    return fail(C, "'" + Type.getAsString(*Policy) + "'",
                "an array without a constant size has no fixed layout");
  else if (const auto *PT = Type->getAs<PointerType>())
    Result = pointer(Type, PT, C);
  else if (Type->isMemberPointerType())
    return fail(C, "a member pointer", "it is code/layout-dependent, not data");
  else if (Type->isAtomicType())
    return fail(C, "an _Atomic object", "atomics are synchronisation state");
  else if (const auto *RT = Type->getAs<RecordType>())
    Result = record(Type, RT->getDecl(), C);
  else
    return fail(C, "'" + Type.getAsString(*Policy) + "'",
                "this kind of type is not supported");
  if (Result != symcr::kNoType)
    Walked[Key] = Result;
  return Result;
}

std::uint32_t TypeWalker::scalar(const BuiltinType *BT, const WalkContext &C) {
  TypeModel Model;
  Model.Size = Context.getTypeSizeInChars(BT).getQuantity();
  Model.Align = Context.getTypeAlignInChars(BT).getQuantity();
  if (BT->isBooleanType()) {
    Model.Kind = symcr::Kind::Bool;
  } else if (BT->isFloatingPoint()) {
    const llvm::fltSemantics &Semantics =
        Context.getFloatTypeSemantics(QualType(BT, 0));
    if (&Semantics != &llvm::APFloat::IEEEsingle() &&
        &Semantics != &llvm::APFloat::IEEEdouble() &&
        &Semantics != &llvm::APFloat::x87DoubleExtended())
      return fail(
          C, "'" + BT->getName(*Policy).str() + "'",
          "only binary32, binary64 and x87 extended floats are supported");
    Model.Kind = symcr::Kind::Float;
  } else if (BT->isIntegerType()) {
    if (Model.Size != 1 && Model.Size != 2 && Model.Size != 4 &&
        Model.Size != 8)
      return fail(C, "'" + BT->getName(*Policy).str() + "'",
                  "integers wider than 64 bits are not supported");
    Model.Kind =
        BT->isSignedIntegerType() ? symcr::Kind::Int : symcr::Kind::UInt;
  } else {
    return fail(C, "'" + BT->getName(*Policy).str() + "'",
                "it holds no restorable value");
  }
  Model.Name = canonicalName(QualType(BT, 0), C);
  Model.Spelling = BT->getName(*Policy).str();
  bool Fresh;
  std::uint32_t Index = reserve(Model.Name, Model.Name, Fresh);
  store(Index, std::move(Model), C);
  return Index;
}

TypeModel TypeWalker::describe(QualType Type, const WalkContext &C) {
  TypeModel Model;
  Model.Name = canonicalName(Type, C);
  Model.Spelling = spelling(Type);
  Model.Accessible = accessible(Type);
  Model.Size = Context.getTypeSizeInChars(Type).getQuantity();
  Model.Align = Context.getTypeAlignInChars(Type).getQuantity();
  return Model;
}

std::uint32_t TypeWalker::enumeration(QualType Type, const EnumDecl *ED,
                                      const WalkContext &C) {
  ED = ED->getDefinition();
  if (!ED)
    return fail(C, "an incomplete enum", "its enumerators are unknown");
  TypeModel Model = describe(Type, C);
  Model.Kind = symcr::Kind::Enum;
  if (ED->isScoped())
    Model.Flags |= symcr::kTypeScopedEnum;
  Model.RenamedFrom = renamedFromAnnotations(ED);
  qualifyLike(Model.Name, Model.RenamedFrom);
  for (const EnumConstantDecl *E : ED->enumerators()) {
    const llvm::APSInt &Value = E->getInitVal();
    std::int64_t Stored = Value.isSigned()
                              ? Value.getSExtValue()
                              : static_cast<std::int64_t>(Value.getZExtValue());
    Model.Enumerators.emplace_back(E->getName().str(), Stored);
  }
  bool Fresh;
  std::uint32_t Index = reserve(Model.Name, Model.Name, Fresh);
  Walked[{Type.getTypePtr(), C.Shallow}] = Index;
  Model.Element = walk(ED->getIntegerType(), C);
  if (Model.Element == symcr::kNoType)
    return symcr::kNoType;
  store(Index, std::move(Model), C);
  return Index;
}

std::uint32_t TypeWalker::array(QualType Type, const ConstantArrayType *AT,
                                const WalkContext &C) {
  TypeModel Model;
  Model.Kind = symcr::Kind::Array;
  Model.Name = canonicalName(Type, C);
  Model.Size = Context.getTypeSizeInChars(Type).getQuantity();
  Model.Align = Context.getTypeAlignInChars(Type).getQuantity();
  Model.Count = AT->getSize().getZExtValue();
  WalkContext Element = C;
  Element.Path += "[]";
  Element.Shallow = false;
  Model.Element = walk(AT->getElementType(), Element);
  if (Model.Element == symcr::kNoType)
    return symcr::kNoType;
  bool Fresh;
  std::uint32_t Index = reserve(Model.Name, Model.Name, Fresh);
  store(Index, std::move(Model), C);
  return Index;
}

bool TypeWalker::checkPointee(QualType Pointee, const WalkContext &C,
                              const char *Holder) {
  Pointee = Pointee.getCanonicalType();
  if (Pointee->isFunctionType()) {
    fail(C, std::string("a function ") + Holder,
         "code addresses differ between builds; re-register callbacks after "
         "restore");
    return false;
  }
  if (Pointee->isVoidType()) {
    fail(C, std::string("a void ") + Holder, "the pointee's type is unknown");
    return false;
  }
  if (const auto *RT = Pointee->getAs<RecordType>()) {
    const RecordDecl *RD =
        completeDefinition(RT->getDecl(), RT->getDecl()->getLocation());
    std::string Name = RT->getDecl()->getName().str();
    if (Name == "_IO_FILE" || Name == "FILE")
      return fail(C, "a FILE handle",
                  "file handles are process state; reopen after "
                  "restore"),
             false;
    if (!RD) {
      fail(C,
           std::string("a ") + Holder + " to incomplete type '" +
               Pointee.getAsString(*Policy) + "'",
           "its layout is unknown here");
      return false;
    }
    // A raw pointer to a polymorphic class is a reference to a checkpointed
    // object (a member, an element), or a heap object saved as its dynamic
    // type (findDynamicTypes). An owning smart pointer would rebuild its
    // object as its static type, slicing it: refused.
    if (const auto *CRD = dyn_cast<CXXRecordDecl>(RD))
      if (CRD->isPolymorphic() && !CRD->hasAttr<FinalAttr>() &&
          llvm::StringRef(Holder) != "pointer") {
        fail(C,
             std::string("a ") + Holder + " to polymorphic class '" +
                 Pointee.getAsString(*Policy) + "'",
             "the pointee's dynamic type may differ from the static type (make "
             "the class "
             "final, or skip the pointer)");
        return false;
      }
  }
  return true;
}

std::uint32_t TypeWalker::pointer(QualType Type, const PointerType *PT,
                                  const WalkContext &C) {
  QualType Pointee = PT->getPointeeType();
  if (!checkPointee(Pointee, C, "pointer"))
    return symcr::kNoType;
  TypeModel Model;
  Model.Kind = symcr::Kind::Pointer;
  Model.Name = canonicalName(Type, C);
  Model.Size = Context.getTypeSizeInChars(Type).getQuantity();
  Model.Align = Context.getTypeAlignInChars(Type).getQuantity();
  bool Fresh;
  std::uint32_t Index = reserve(Model.Name, Model.Name, Fresh);
  Walked[{Type.getTypePtr(), false}] = Index;
  Model.Element = walk(Pointee, intoPointee(C, Model.Name));
  if (Model.Element == symcr::kNoType)
    return symcr::kNoType;
  // A polymorphic pointee is created by restore as its dynamic type, which
  // has a Lifecycle of its own; the pointee itself may be abstract.
  std::uint32_t Element = Model.Element;
  if (!(Program.Types[Element].Flags & symcr::kTypePolymorphic))
    Program.Types[Element].NeedsLifecycle = true;
  store(Index, std::move(Model), C);
  if (Program.Types[Element].Flags & symcr::kTypePolymorphic)
    findDynamicTypes(Pointee->getAsCXXRecordDecl(), Element,
                     intoPointee(C, Program.Types[Index].Name));
  return Index;
}

std::uint32_t TypeWalker::neverOwningPointer(QualType Type,
                                             const WalkContext &C) {
  Type = Type.getCanonicalType().getUnqualifiedType();
  QualType Pointee = Type->getAs<PointerType>()->getPointeeType();
  if (!checkPointee(Pointee, C, "pointer"))
    return symcr::kNoType;
  TypeModel Model;
  Model.Kind = symcr::Kind::Pointer;
  Model.Flags = symcr::kTypeNeverOwns;
  Model.Name = canonicalName(Type, C);
  Model.Size = Context.getTypeSizeInChars(Type).getQuantity();
  Model.Align = Context.getTypeAlignInChars(Type).getQuantity();
  // Its own slot beside the owning pointer of the same name: the flag differs.
  bool Fresh;
  std::uint32_t Index =
      reserve(Model.Name + " (never owns)", Model.Name, Fresh);
  Model.Element = walk(Pointee, intoPointee(C, Model.Name));
  if (Model.Element == symcr::kNoType)
    return symcr::kNoType;
  store(Index, std::move(Model), C);
  return Index;
}

std::string TypeWalker::whyNotCreatable(const CXXRecordDecl *Class) {
  std::string Why;
  if (isSkippedType(Class, Why))
    return "skipped (" + Why + ")";
  if (Class->getNumVBases() > 0)
    return "it has virtual bases";
  QualType Type = Context.getRecordType(Class);
  if (spelling(Type).empty() || !accessible(Type))
    return "it cannot be named outside its scope";
  auto *Mutable = const_cast<CXXRecordDecl *>(Class);
  const CXXConstructorDecl *Constructor =
      S ? S->LookupDefaultConstructor(Mutable) : nullptr;
  if (!S ? !Class->hasDefaultConstructor()
         : !Constructor || Constructor->isDeleted() ||
               Constructor->getAccess() != AS_public)
    return "no public default constructor";
  const CXXDestructorDecl *Destructor =
      S ? S->LookupDestructor(Mutable) : nullptr;
  if (S && (!Destructor || Destructor->isDeleted() ||
            Destructor->getAccess() != AS_public))
    return "no public destructor";
  return "";
}

std::uint32_t TypeWalker::tentativeWalk(QualType Type, const WalkContext &C,
                                        std::string &Why) {
  auto Done = Walked.find({Type.getCanonicalType().getTypePtr(), C.Shallow});
  if (Done != Walked.end())
    return Done->second;
  std::vector<TypeModel> Types = Program.Types;
  std::map<std::string, std::uint32_t> TypeIndex = Program.TypeIndex;
  auto WalkedBefore = Walked;
  auto SoughtBefore = DynamicTypesSought;
  Diagnostics Quiet(/*Quiet=*/true);
  Diagnostics *Outer = Sink;
  Sink = &Quiet;
  std::uint32_t Index = walk(Type, C);
  Sink = Outer;
  if (Index != symcr::kNoType && Quiet.clean())
    return Index;
  Why = Quiet.firstProblem();
  Program.Types = std::move(Types);
  Program.TypeIndex = std::move(TypeIndex);
  Walked = std::move(WalkedBefore);
  DynamicTypesSought = std::move(SoughtBefore);
  return symcr::kNoType;
}

void TypeWalker::findDynamicTypes(const CXXRecordDecl *Base,
                                  std::uint32_t BaseIndex,
                                  const WalkContext &C) {
  if (!Base || !PolymorphicClasses ||
      !DynamicTypesSought.insert(BaseIndex).second)
    return;
  Base = Base->getDefinition();
  if (Program.Types[BaseIndex].DynamicTypesReachedBy.empty()) {
    Program.Types[BaseIndex].DynamicTypesReachedBy =
        C.Path.substr(0, C.Path.size() - 2);
    Program.Types[BaseIndex].DynamicTypesReachedAt = C.Where;
    Program.Types[BaseIndex].DynamicTypesSkipHint = C.SkipHint;
  }
  auto NotCreatable = [&](const std::string &Name, const std::string &Why) {
    std::string Entry = Name + ": " + Why;
    std::vector<std::string> &List = Program.Types[BaseIndex].NotDynamicTypes;
    if (std::find(List.begin(), List.end(), Entry) == List.end())
      List.push_back(Entry);
  };
  // Saving recognises a class by its vtable (vtableSymbol: Itanium C++ ABI
  // only).
  auto *VTables = dyn_cast<ItaniumVTableContext>(Context.getVTableContext());
  if (vtableSymbol(Context, Base).empty() || !VTables) {
    NotCreatable(Base->getNameAsString(),
                 "the target's C++ ABI is not the Itanium one");
    return;
  }
  for (const CXXRecordDecl *Class : *PolymorphicClasses) {
    if (Class != Base && !Class->isDerivedFrom(Base))
      continue;
    if (Class->isAbstract())
      continue; // never an object's dynamic type
    std::string Name = canonicalRecordName(Class);
    std::string Why = whyNotCreatable(Class);
    QualType Type = Context.getRecordType(Class);
    std::uint32_t Index = symcr::kNoType;
    if (Why.empty()) {
      WalkContext Candidate = C;
      Candidate.Path = C.Path + "(" + Name + ")";
      Index = tentativeWalk(Type, Candidate, Why);
    }
    if (Index == symcr::kNoType) {
      NotCreatable(Name, Why);
      continue;
    }
    TypeModel &Dynamic = Program.Types[Index];
    Dynamic.NeedsLifecycle = true;
    Dynamic.VtableSymbol = vtableSymbol(Context, Class);
    if (const CXXMethodDecl *Key = vtableKeyFunction(Context, Class))
      Dynamic.VtableKeyFunction = Key->getQualifiedNameAsString();
    Dynamic.VtableAddressPoint =
        VTables->getVTableLayout(Class)
            .getAddressPoint(BaseSubobject(Class, CharUnits::Zero()))
            .AddressPointIndex;
    std::vector<std::uint32_t> &List = Program.Types[BaseIndex].DynamicTypes;
    if (std::find(List.begin(), List.end(), Index) == List.end())
      List.push_back(Index);
  }
}

bool TypeWalker::fillFields(const RecordDecl *RD, TypeModel &Model,
                            const WalkContext &C) {
  const ASTRecordLayout &Layout = Context.getASTRecordLayout(RD);
  const auto *CRD = dyn_cast<CXXRecordDecl>(RD);
  std::vector<std::string> Keys = recordKeys(RD);
  std::string OwnerName = Keys.empty() ? Model.Name : Keys.front();
  bool Ok = true;
  auto Lookup = [&](const auto &Map, const std::string &Field) {
    for (const std::string &K : Keys) {
      auto It = Map.find(std::make_pair(K, Field));
      if (It != Map.end())
        return It;
    }
    return Map.end();
  };
  if (CRD) {
    for (const CXXBaseSpecifier &Base : CRD->bases()) {
      const CXXRecordDecl *BaseRD = Base.getType()->getAsCXXRecordDecl();
      if (!BaseRD)
        continue;
      WalkContext B = C;
      B.Where = locationOf(Context, Base.getBeginLoc());
      std::string Why;
      if (isSkippedType(BaseRD, Why)) {
        Model.Skipped.push_back({"base " + BaseRD->getNameAsString(), Why});
        continue;
      }
      if (BaseRD->isEmpty() && !BaseRD->isPolymorphic())
        continue; // an empty base holds no state
      FieldModel Field;
      Field.Type = walk(Base.getType(), B);
      if (Field.Type == symcr::kNoType) {
        Ok = false;
        continue;
      }
      Field.Name = Program.Types[Field.Type].Name;
      Field.Flags = symcr::kFieldBase;
      Field.Offset = Layout.getBaseClassOffset(BaseRD).getQuantity();
      Model.Fields.push_back(Field);
    }
  }
  bool StandardLayout = !CRD || CRD->isStandardLayout();
  for (const FieldDecl *FD : RD->fields()) {
    if (FD->isUnnamedBitfield())
      continue;
    unsigned FieldIndex = FD->getFieldIndex();
    std::string Name = FD->getName().str();
    bool Anonymous = FD->isAnonymousStructOrUnion() || Name.empty();
    if (Anonymous) {
      const RecordDecl *Inner = FD->getType()->getAsRecordDecl();
      Name = std::string("(anonymous ") +
             (Inner && Inner->isUnion() ? "union" : "struct") + " at field " +
             std::to_string(FieldIndex) + ")";
    }
    WalkContext F = C;
    // "sim->lock", not "sim->.lock"
    F.Path =
        C.Path + (llvm::StringRef(C.Path).endswith("->") ? "" : ".") + Name;
    F.Enclosing = C.SkipHint.empty()
                      ? MemberRef()
                      : MemberRef{C.Path, C.SkipHint, Model.Name, C.Where};
    F.Where = locationOf(Context, FD->getLocation());
    F.SkipHint = OwnerName + "::" + Name;
    F.Shallow = false;
    F.AnonymousName.clear();
    std::string Why;
    if (const char *Why = leftToNewBuild(FD->getType())) {
      Model.LeftToNewBuild.push_back({Name, Why});
      Model.Flags |= symcr::kTypeLeavesMembers;
      continue;
    }
    if (hasAnnotation(FD, "skip")) {
      Model.Skipped.push_back({Name, "SYMCR_SKIP"});
      continue;
    }
    if (auto It = Lookup(Select.SkippedFields, Name);
        It != Select.SkippedFields.end()) {
      Model.Skipped.push_back({Name, It->second});
      continue;
    }
    QualType FieldType = FD->getType();
    QualType Innermost = Context.getBaseElementType(FieldType);
    if (const RecordDecl *FieldRD = Innermost->getAsRecordDecl())
      if (isSkippedType(FieldRD, Why)) {
        Model.Skipped.push_back(
            {Name, "type " + recordName(FieldRD, WalkContext()) + ": " + Why});
        continue;
      }
    if (C.Shallow) {
      bool Included =
          hasAnnotation(FD, "include") ||
          Lookup(Select.IncludedFields, Name) != Select.IncludedFields.end();
      bool Plain = Innermost->isScalarType() && !Innermost->isPointerType() &&
                   !Innermost->isMemberPointerType();
      if (!Included && !Plain) {
        Model.Skipped.push_back(
            {Name, "not selected for a shallow root "
                   "(SYMCR_INCLUDE or '#pragma symcr include(" +
                       OwnerName + "::" + Name + ")' selects it)"});
        continue;
      }
    }
    if (Anonymous) {
      const RecordDecl *Inner = FieldType->getAsRecordDecl();
      if (Inner)
        AnonymousNames[Inner] = Model.Name + "::" + Name;
    } else if (const RecordDecl *Inner = FieldType->getAsRecordDecl()) {
      if (!Inner->getIdentifier() && !Inner->getTypedefNameForAnonDecl())
        AnonymousNames.emplace(
            Inner, Model.Name + "::(anonymous " +
                       (Inner->isUnion() ? "union" : "struct") + " at field " +
                       std::to_string(FieldIndex) + ")");
    }
    FieldModel Field;
    Field.Name = Name;
    Field.RestoresAlone = hasAnnotation(FD, "restores_alone") ||
                          Lookup(Select.RestoresAloneFields, Name) !=
                              Select.RestoresAloneFields.end();
    bool NotOwner =
        hasAnnotation(FD, "not_owner") ||
        Lookup(Select.NotOwnerFields, Name) != Select.NotOwnerFields.end();
    if (NotOwner && !FieldType.getCanonicalType()->isPointerType()) {
      Sink->error(F.Where,
                  "member '" + F.Path +
                      "' is declared never to own a heap object "
                      "(SYMCR_NOT_OWNER, not_owner), but it is not a raw "
                      "pointer");
      Ok = false;
      continue;
    }
    Field.Type =
        NotOwner ? neverOwningPointer(FieldType, F) : walk(FieldType, F);
    if (Field.Type == symcr::kNoType) {
      Ok = false;
      continue;
    }
    if (Field.RestoresAlone && !isStateFlag(Program.Types[Field.Type])) {
      Sink->error(
          F.Where,
          "member '" + F.Path +
              "' is declared to restore alone (SYMCR_RESTORES_ALONE, "
              "restores_alone), but it is not a boolean or enum state flag");
      Ok = false;
      continue;
    }
    std::uint64_t Bits = Layout.getFieldOffset(FieldIndex);
    if (FD->isBitField()) {
      std::uint64_t UnitBytes =
          Context.getTypeSizeInChars(FieldType).getQuantity();
      Field.BitWidth = FD->getBitWidthValue(Context);
      if (Field.BitWidth == 0)
        continue;
      std::uint64_t UnitBits = UnitBytes * 8;
      Field.Offset = (Bits / UnitBits) * UnitBytes;
      Field.BitOffset = static_cast<unsigned>(Bits - Field.Offset * 8);
      if (Field.BitOffset + Field.BitWidth > UnitBits) {
        Sink->error(F.Where, "bit-field '" + F.Path +
                                 "' straddles its storage unit "
                                 "(packed layout); not supported");
        Ok = false;
        continue;
      }
    } else {
      Field.Offset = Bits / 8;
      bool Public = FD->getAccess() == AS_public || FD->getAccess() == AS_none;
      if (StandardLayout && Public && !Anonymous && !Model.Spelling.empty())
        Field.OffsetCheckMember = Name;
    }
    Field.RenamedFrom = renamedFromAnnotations(FD);
    if (auto It = Lookup(Select.FieldRenames, Name);
        It != Select.FieldRenames.end())
      Field.RenamedFrom.insert(Field.RenamedFrom.end(), It->second.begin(),
                               It->second.end());
    for (const std::string &A : symcrAnnotations(FD)) {
      llvm::StringRef Range(A);
      if (!Range.consume_front("range:"))
        continue;
      auto Bounds = Range.split(':');
      char *End1 = nullptr, *End2 = nullptr;
      std::string Lo = Bounds.first.str(), Hi = Bounds.second.str();
      Field.RangeMin = std::strtod(Lo.c_str(), &End1);
      Field.RangeMax = std::strtod(Hi.c_str(), &End2);
      if (Lo.empty() || Hi.empty() || *End1 || *End2 ||
          !(Field.RangeMin <= Field.RangeMax)) { // NaN too
        Sink->error(F.Where,
                    "SYMCR_RANGE needs two numeric bounds lo <= hi, got '" +
                        Range.str() + "'");
        Ok = false;
      }
      for (const auto &[Text, Value] :
           {std::pair{Lo, Field.RangeMin}, std::pair{Hi, Field.RangeMax}}) {
        const std::string Inexact = inexactRangeBound(Text, Value);
        if (!Inexact.empty()) {
          Sink->error(F.Where,
                      "member '" + F.Path + "': SYMCR_RANGE's " + Inexact);
          Ok = false;
        }
      }
      Field.Flags |= symcr::kFieldHasRange;
    }
    if (auto It = Lookup(Select.FieldRanges, Name);
        It != Select.FieldRanges.end()) {
      if ((Field.Flags & symcr::kFieldHasRange) &&
          (Field.RangeMin != It->second.first ||
           Field.RangeMax != It->second.second)) {
        Sink->error(F.Where, "member '" + F.Path +
                                 "' has SYMCR_RANGE and a different "
                                 "range directive");
        Ok = false;
      }
      Field.RangeMin = It->second.first;
      Field.RangeMax = It->second.second;
      Field.Flags |= symcr::kFieldHasRange;
    }
    if (Field.Flags & symcr::kFieldHasRange) {
      // Restore checks a range on a number; on anything else it would be
      // ignored without a word.
      const TypeModel &Ranged = Program.Types[Field.Type];
      const symcr::Kind K = Ranged.Kind;
      if (K != symcr::Kind::Bool && K != symcr::Kind::Int &&
          K != symcr::Kind::UInt && K != symcr::Kind::Float &&
          K != symcr::Kind::Enum) {
        Sink->error(F.Where, "SYMCR_RANGE on '" + F.Path + "', a " +
                                 Ranged.Name +
                                 ": a range checks one number; put it on a "
                                 "numeric member, or check the elements or "
                                 "members in a symcr_validate hook");
        Ok = false;
      }
    }
    const auto TimeDirective = Lookup(Select.FieldTimes, Name);
    if (!fieldTime(FD,
                   TimeDirective != Select.FieldTimes.end()
                       ? &TimeDirective->second
                       : nullptr,
                   Field, F))
      Ok = false;
    Model.Fields.push_back(Field);
  }
  return Ok;
}

std::uint32_t TypeWalker::record(QualType Type, const RecordDecl *Decl,
                                 const WalkContext &C) {
  const RecordDecl *RD = completeDefinition(Decl, Decl->getLocation());
  if (!RD)
    return fail(C, "incomplete type '" + Type.getAsString(*Policy) + "'",
                "its layout is unknown here");
  if (RD->isInvalidDecl() || RD->isDependentType())
    return fail(C, "'" + Type.getAsString(*Policy) + "'",
                "the type is invalid or dependent");
  llvm::StringRef StdName;
  if (isStdTemplate(RD, StdName))
    return stdRecord(Type, RD, StdName, C);
  const auto *CRD = dyn_cast<CXXRecordDecl>(RD);
  if (CRD && CRD->isLambda())
    return fail(C, "a lambda", "closures hold code");
  if (CRD && CRD->getNumVBases() > 0)
    return fail(C, "class '" + CRD->getNameAsString() + "' with virtual bases",
                "virtual base offsets are only known at run time");
  std::string PlainName = NameIndex::qualifiedName(RD);
  if (llvm::StringRef(PlainName).startswith("pthread_") ||
      llvm::StringRef(PlainName).startswith("__pthread") ||
      PlainName == "_IO_FILE")
    return fail(C, "'" + PlainName + "'",
                "threads, locks and files are process state");

  TypeModel Model = describe(Type, C);
  Model.RenamedFrom = renamedFromAnnotations(RD);
  for (const std::string &K : recordKeys(RD)) {
    auto It = Select.TypeRenames.find(K);
    if (It != Select.TypeRenames.end())
      Model.RenamedFrom.insert(Model.RenamedFrom.end(), It->second.begin(),
                               It->second.end());
  }
  qualifyLike(Model.Name, Model.RenamedFrom);
  if (RD->isUnion()) {
    Model.Kind = symcr::Kind::Union;
    if (CRD && !CRD->isTriviallyCopyable())
      return fail(
          C, "union '" + Model.Name + "' with non-trivial members",
          "a union is restored as raw bytes, which only works for trivially "
          "copyable members");
    // Raw bytes must not carry addresses of the old process.
    std::vector<QualType> Pending{Type};
    while (!Pending.empty()) {
      QualType T = Context.getBaseElementType(Pending.back());
      Pending.pop_back();
      if (T->isPointerType() || T->isMemberPointerType() ||
          T->isReferenceType())
        return fail(C, "union '" + Model.Name + "' containing a pointer",
                    "its raw bytes would hold addresses of the old process");
      if (const RecordDecl *Inner = T->getAsRecordDecl())
        if (const RecordDecl *Def = Inner->getDefinition())
          for (const FieldDecl *F : Def->fields())
            Pending.push_back(F->getType());
    }
    bool Fresh;
    std::uint32_t Index = reserve(Model.Name, Model.Name, Fresh);
    store(Index, std::move(Model), C);
    return Index;
  }
  Model.Kind = symcr::Kind::Struct;
  if (CRD && CRD->isPolymorphic() && !CRD->hasAttr<FinalAttr>())
    Model.Flags |= symcr::kTypePolymorphic;
  std::string Key = Model.Name;
  if (C.Shallow) {
    Model.Flags |= symcr::kTypeShallow;
    Key += " (shallow)";
  }
  bool Fresh;
  std::uint32_t Index = reserve(Key, Model.Name, Fresh);
  Walked[{Type.getTypePtr(), C.Shallow}] = Index;
  if (!fillFields(RD, Model, C))
    return symcr::kNoType;
  if (CRD && !Model.Spelling.empty() &&
      Select.Validated.count(
          Type.getCanonicalType().getUnqualifiedType().getTypePtr())) {
    Model.HasValidate = true;
    // Restore checks a staged copy, created with the lifecycle unless the
    // type is plain bytes.
    if (CRD->hasDefaultConstructor())
      Model.NeedsLifecycle = true;
  }
  if (CRD && !Model.Spelling.empty() &&
      Select.Migrated.count(
          Type.getCanonicalType().getUnqualifiedType().getTypePtr())) {
    Model.HasMigrate = true;
    Model.Flags |= symcr::kTypeMigrated;
  }
  store(Index, std::move(Model), C);
  return Index;
}

/// The classes (Struct types) the raw pointers reachable from \p RootTypes
/// point to.
static std::set<std::uint32_t>
pointeeClasses(const ProgramModel &Program,
               const std::vector<std::uint32_t> &RootTypes) {
  std::set<std::uint32_t> Seen, Pointees;
  std::vector<std::uint32_t> Pending(RootTypes.begin(), RootTypes.end());
  while (!Pending.empty()) {
    std::uint32_t T = Pending.back();
    Pending.pop_back();
    if (T >= Program.Types.size() || !Seen.insert(T).second)
      continue;
    const TypeModel &Model = Program.Types[T];
    for (const FieldModel &F : Model.Fields)
      Pending.push_back(F.Type);
    for (std::uint32_t A : Model.Alternatives)
      Pending.push_back(A);
    for (std::uint32_t D : Model.DynamicTypes)
      Pending.push_back(D);
    if (Model.Element != symcr::kNoType)
      Pending.push_back(Model.Element);
    if (Model.Kind == symcr::Kind::Pointer &&
        Model.Element < Program.Types.size() &&
        Program.Types[Model.Element].Kind == symcr::Kind::Struct)
      Pointees.insert(Model.Element);
  }
  return Pointees;
}

void TypeWalker::addReferenceMembers(
    const std::vector<std::tuple<std::string, QualType, std::uint32_t>>
        &ClassRoots,
    const std::vector<std::uint32_t> &RootTypes) {
  if (ClassRoots.empty())
    return;
  std::set<std::uint32_t> Pointees = pointeeClasses(Program, RootTypes);
  if (Pointees.empty())
    return;
  for (const auto &Root : ClassRoots) {
    const std::string &Name = std::get<0>(Root);
    std::uint32_t Index = std::get<2>(Root);
    const RecordDecl *Decl = std::get<1>(Root)->getAsRecordDecl();
    const RecordDecl *RD =
        Decl ? completeDefinition(Decl, SourceLocation()) : nullptr;
    if (!RD || RD->isUnion() ||
        Program.Types[Index].Kind != symcr::Kind::Struct)
      continue;
    const ASTRecordLayout &Layout = Context.getASTRecordLayout(RD);
    std::vector<std::string> Keys = recordKeys(RD);
    std::vector<FieldModel> Members;
    for (const FieldDecl *FD : RD->fields()) {
      std::string Member = FD->getName().str();
      if (Member.empty() || FD->isBitField() || leftToNewBuild(FD->getType()))
        continue;
      const std::vector<FieldModel> &Selected = Program.Types[Index].Fields;
      if (std::any_of(Selected.begin(), Selected.end(),
                      [&](const FieldModel &F) { return F.Name == Member; }))
        continue;
      WalkContext C;
      C.Path = Name + "." + Member;
      C.Where = locationOf(Context, FD->getLocation());
      std::uint32_t Type = referenceView(FD->getType(), Pointees, Name, C, 0);
      if (Type == symcr::kNoType)
        continue;
      FieldModel Field;
      Field.Name = Member;
      Field.Type = Type;
      Field.Offset = Layout.getFieldOffset(FD->getFieldIndex()) / 8;
      Field.RenamedFrom = renamedFromAnnotations(FD);
      for (const std::string &K : Keys) {
        auto It = Select.FieldRenames.find({K, Member});
        if (It != Select.FieldRenames.end())
          Field.RenamedFrom.insert(Field.RenamedFrom.end(), It->second.begin(),
                                   It->second.end());
      }
      Members.push_back(std::move(Field));
    }
    if (Members.empty())
      continue;
    TypeModel &Model = Program.Types[Index];
    Model.ReferenceMembers = std::move(Members);
    Model.Flags |= symcr::kTypeReferenceMembers;
  }
}

std::uint32_t TypeWalker::referenceView(QualType Type,
                                        const std::set<std::uint32_t> &Pointees,
                                        const std::string &Root,
                                        const WalkContext &C, int Depth) {
  Type = Type.getCanonicalType().getUnqualifiedType();
  if (Depth > 64)
    return symcr::kNoType;
  auto Done = Views.find({Type.getTypePtr(), Root});
  if (Done != Views.end())
    return Done->second;
  std::uint32_t Result = symcr::kNoType;
  // "ModeLoiter (references of vehicle)": a view is its root's, so that two
  // roots selecting differently never describe one type two ways.
  const std::string Suffix = " (references of " + Root + ")";
  if (const auto *AT = Context.getAsConstantArrayType(Type)) {
    std::uint32_t Element =
        referenceView(AT->getElementType(), Pointees, Root, C, Depth + 1);
    if (Element == symcr::kNoType)
      return symcr::kNoType;
    if (Pointees.count(Element) &&
        !(Program.Types[Element].Flags & symcr::kTypeShallow)) {
      Result = walk(Type, C); // an array of a pointee class: described in full
    } else {
      TypeModel Model;
      Model.Kind = symcr::Kind::Array;
      Model.Flags = symcr::kTypeShallow;
      Model.Name = canonicalName(Type, C);
      Model.Size = Context.getTypeSizeInChars(Type).getQuantity();
      Model.Align = Context.getTypeAlignInChars(Type).getQuantity();
      Model.Count = AT->getSize().getZExtValue();
      Model.Element = Element;
      bool Fresh;
      Result = reserve(Model.Name + Suffix, Model.Name, Fresh);
      store(Result, std::move(Model), C);
    }
  } else if (const RecordDecl *Decl = Type->getAsRecordDecl()) {
    auto Walked = this->Walked.find({Type.getTypePtr(), false});
    if (Walked != this->Walked.end() && Pointees.count(Walked->second))
      return Walked->second;
    const RecordDecl *RD = completeDefinition(Decl, Decl->getLocation());
    llvm::StringRef StdName;
    const auto *CRD = dyn_cast_or_null<CXXRecordDecl>(RD);
    if (!RD || RD->isUnion() || RD->isInvalidDecl() || RD->isDependentType() ||
        isStdTemplate(RD, StdName) ||
        (CRD && (CRD->isLambda() || CRD->getNumVBases() > 0)))
      return symcr::kNoType;
    const ASTRecordLayout &Layout = Context.getASTRecordLayout(RD);
    TypeModel Model = describe(Type, C);
    Model.Kind = symcr::Kind::Struct;
    Model.Flags = symcr::kTypeShallow | symcr::kTypeReferenceMembers;
    if (CRD) {
      for (const CXXBaseSpecifier &Base : CRD->bases()) {
        const CXXRecordDecl *BaseRD = Base.getType()->getAsCXXRecordDecl();
        if (!BaseRD)
          continue;
        std::uint32_t BaseType =
            referenceView(Base.getType(), Pointees, Root, C, Depth + 1);
        if (BaseType == symcr::kNoType)
          continue;
        FieldModel Field;
        Field.Name = Program.Types[BaseType].Name;
        Field.Type = BaseType;
        Field.Flags = symcr::kFieldBase;
        Field.Offset = Layout.getBaseClassOffset(BaseRD).getQuantity();
        Model.ReferenceMembers.push_back(std::move(Field));
      }
    }
    for (const FieldDecl *FD : RD->fields()) {
      std::string Member = FD->getName().str();
      if (Member.empty() || FD->isBitField() || leftToNewBuild(FD->getType()))
        continue;
      WalkContext F = C;
      F.Path = C.Path + "." + Member;
      std::uint32_t MemberType =
          referenceView(FD->getType(), Pointees, Root, F, Depth + 1);
      if (MemberType == symcr::kNoType)
        continue;
      FieldModel Field;
      Field.Name = Member;
      Field.Type = MemberType;
      Field.Offset = Layout.getFieldOffset(FD->getFieldIndex()) / 8;
      Field.RenamedFrom = renamedFromAnnotations(FD);
      Model.ReferenceMembers.push_back(std::move(Field));
    }
    if (Model.ReferenceMembers.empty())
      return symcr::kNoType;
    bool Fresh;
    Result = reserve(Model.Name + Suffix, Model.Name, Fresh);
    store(Result, std::move(Model), C);
  }
  if (Result != symcr::kNoType)
    Views[{Type.getTypePtr(), Root}] = Result;
  return Result;
}

} // namespace symcr_gen
